// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/surface_projection.h"

#include <elastica/vertex_faces.h>

#include <algorithm>
#include <cmath>

namespace elastica {
namespace {

Vec3 unitNormal(const TriMesh& mesh, const Face& t) {
  const Vec3 n = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
  const double length = n.norm();
  return length > 0 && std::isfinite(length) ? Vec3(n / length) : Vec3(Vec3::Zero());
}

}  // namespace

Vec3 closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double l2 = ab.squaredNorm();
  if (!(l2 > 0)) return a;
  return a + std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) * ab;
}

std::vector<std::pair<int, int>> sharpEdges(const TriMesh& mesh, double angleDegrees) {
  const double cosine = std::cos(angleDegrees * M_PI / 180);
  const std::vector<std::vector<int>> faces = faceListsOf(mesh);
  std::vector<std::pair<int, int>> sharp;
  for (int a = 0; a < mesh.vertexCount(); ++a) {
    std::vector<std::pair<int, int>> byNeighbour;  // (larger neighbour, face)
    for (int f : faces[a])
      for (int b : mesh.faces[f])
        if (b > a) byNeighbour.emplace_back(b, f);
    std::sort(byNeighbour.begin(), byNeighbour.end());
    for (std::size_t i = 0; i < byNeighbour.size();) {
      std::size_t j = i;
      while (j < byNeighbour.size() && byNeighbour[j].first == byNeighbour[i].first) ++j;
      if (j - i == 2) {
        const Vec3 n0 = unitNormal(mesh, mesh.faces[byNeighbour[i].second]),
                   n1 = unitNormal(mesh, mesh.faces[byNeighbour[i + 1].second]);
        if (n0 != Vec3::Zero() && n1 != Vec3::Zero() && n0.dot(n1) < cosine) sharp.emplace_back(a, byNeighbour[i].first);
      }
      i = j;
    }
  }
  return sharp;
}

Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

SurfaceProjector::SurfaceProjector(const TriMesh& surface, double featureAngleDegrees)
    : surface_(surface), featureAngle_(featureAngleDegrees), sharp_(sharpEdges(surface, featureAngleDegrees)) {
  normal_.reserve(surface_.faces.size());
  for (const Face& t : surface_.faces) normal_.push_back(unitNormal(surface_, t));
  faces_ = BoxTree(faceBoxes(surface_));
  std::vector<Box> boxes;
  for (const auto& [a, b] : sharp_) {
    Box box;
    box.add(surface_.positions[a]);
    box.add(surface_.positions[b]);
    boxes.push_back(box);
  }
  segments_ = BoxTree(boxes);
}

bool SurfaceProjector::project(const Vec3& p, const Vec3& normal, Vec3& onSurface) const {
  const auto [face, d2] = faces_.nearest(p, [&](int f, const Vec3& q) {
    if (normal_[f].dot(normal) < 0 || (normal != Vec3::Zero() && normal_[f].dot(normal) == 0))
      return std::numeric_limits<double>::infinity();
    const Face& t = surface_.faces[f];
    return (closestOnTriangle(q, surface_.positions[t[0]], surface_.positions[t[1]], surface_.positions[t[2]]) - q)
        .squaredNorm();
  });
  if (face < 0) return false;
  const Face& t = surface_.faces[face];
  onSurface = closestOnTriangle(p, surface_.positions[t[0]], surface_.positions[t[1]], surface_.positions[t[2]]);
  return true;
}

bool SurfaceProjector::projectOnSharpEdge(const Vec3& p, Vec3& onEdge) const {
  const auto [segment, d2] = segments_.nearest(p, [&](int s, const Vec3& q) {
    return (closestOnSegment(q, surface_.positions[sharp_[s].first], surface_.positions[sharp_[s].second]) - q)
        .squaredNorm();
  });
  if (segment < 0) return false;
  onEdge = closestOnSegment(p, surface_.positions[sharp_[segment].first], surface_.positions[sharp_[segment].second]);
  return true;
}

}  // namespace elastica
