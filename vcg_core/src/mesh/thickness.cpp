// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/thickness.h"
#include "mesh/box.h"
#include "mesh/face_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace elastica {
namespace {

// Entry distance of the ray o + t d (t >= 0) into the box, or infinity if it misses it.
double rayEntersBox(const Vec3& o, const Vec3& invD, const Box& box) {
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    double a = (box.lo[k] - o[k]) * invD[k], b = (box.hi[k] - o[k]) * invD[k];
    if (std::isnan(a) || std::isnan(b)) {  // a zero direction component along a slab face: inside or not
      if (o[k] < box.lo[k] || o[k] > box.hi[k]) return std::numeric_limits<double>::infinity();
      continue;
    }
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return std::numeric_limits<double>::infinity();
  }
  return t0;
}

// Möller–Trumbore: the distance along the ray to triangle abc (edges included), or infinity.
double rayHitsTriangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (det == 0 || !std::isfinite(det)) return std::numeric_limits<double>::infinity();
  const double inv = 1 / det;
  const Vec3 s = o - a;
  const double u = s.dot(p) * inv;
  if (u < 0 || u > 1) return std::numeric_limits<double>::infinity();
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < 0 || u + v > 1) return std::numeric_limits<double>::infinity();
  const double t = e2.dot(q) * inv;
  return t > 0 ? t : std::numeric_limits<double>::infinity();
}

}  // namespace

std::vector<double> faceThickness(const TriMesh& mesh) {
  const int nf = mesh.faceCount();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> thickness(nf, inf);
  // Six times the enclosed volume: negative when the faces' normals point inward.
  double volume = 0;
  for (const Face& t : mesh.faces) volume += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]]));
  const double inward = volume < 0 ? 1 : -1;
  const BoxTree tree(faceBoxes(mesh));
  std::vector<int> stack;
  for (int f = 0; f < nf; ++f) {
    const Face& t = mesh.faces[f];
    const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    const Vec3 n = (b - a).cross(c - a);
    const double length = n.norm();
    if (!(length > 0) || !std::isfinite(length)) continue;
    const Vec3 d = inward * n / length;
    const Vec3 o = (a + b + c) / 3;
    const Vec3 invD(1 / d.x(), 1 / d.y(), 1 / d.z());
    double best = inf;
    stack.assign(1, 0);
    while (!stack.empty()) {
      const BoxTree::Node& node = tree.nodes[stack.back()];
      stack.pop_back();
      if (!(rayEntersBox(o, invD, node.box) < best)) continue;
      if (node.left < 0) {
        for (int i = node.begin; i < node.end; ++i) {
          const int g = tree.order[i];
          if (g == f) continue;
          const Face& s = mesh.faces[g];
          best = std::min(best, rayHitsTriangle(o, d, mesh.positions[s[0]], mesh.positions[s[1]], mesh.positions[s[2]]));
        }
      } else {
        stack.push_back(node.left);
        stack.push_back(node.right);
      }
    }
    thickness[f] = best;
  }
  return thickness;
}

double thinnestFeature(const TriMesh& mesh, double quantile) {
  const std::vector<double> thickness = faceThickness(mesh);
  std::vector<std::pair<double, double>> byThickness;  // (thickness, area)
  double total = 0;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (!std::isfinite(thickness[f])) continue;
    const Face& t = mesh.faces[f];
    const double area =
        0.5 * (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).norm();
    byThickness.emplace_back(thickness[f], area);
    total += area;
  }
  if (byThickness.empty() || !(total > 0)) return 0;
  std::sort(byThickness.begin(), byThickness.end());
  const double wanted = std::clamp(quantile, 0.0, 1.0) * total;
  double below = 0;
  for (const auto& [t, area] : byThickness) {
    below += area;
    if (below >= wanted) return t;
  }
  return byThickness.back().first;
}

}  // namespace elastica
