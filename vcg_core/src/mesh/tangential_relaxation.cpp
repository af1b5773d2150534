// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/geometry.h>
#include <elastica/mesh_quality.h>
#include <elastica/topology.h>
#include "mesh/tangential_relaxation.h"

#include <algorithm>

namespace elastica {
namespace {

// Twice the area times the unit normal of face f.
Vec3 areaNormal(const TriMesh& mesh, int f) {
  const auto& t = mesh.faces[f];
  return (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
}

// `faceFlags`, or every face when it is empty.
std::vector<std::uint8_t> flaggedOrAll(const TriMesh& mesh, const std::vector<std::uint8_t>& faceFlags) {
  return faceFlags.empty() ? std::vector<std::uint8_t>(mesh.faces.size(), 1) : faceFlags;
}

// One Jacobi pass of p_i ← p_i + damping · Π_i(c_i − p_i) with the unit normals `normal`.
void relaxPass(const Topology& topo, const std::vector<std::uint8_t>& free, const std::vector<Vec3>& normal,
               double damping, std::vector<Vec3>& positions, std::vector<Vec3>& next) {
  next = positions;
  for (int v = 0; v < topo.vertexCount(); ++v) {
    if (!free[v] || topo.valence(v) == 0) continue;
    Vec3 c = Vec3::Zero();
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) c += positions[topo.ringVertex(k)];
    const Vec3 d = c / topo.valence(v) - positions[v];
    const Vec3& n = normal[v];
    next[v] += damping * (d - d.dot(n) * n);
  }
  positions.swap(next);
}

// Area-weighted face normals summed at each vertex, then over `rings` more rings, normalised.
void smoothedNormals(const Topology& topo, const TriMesh& mesh, int rings, std::vector<Vec3>& normal,
                     std::vector<Vec3>& scratch) {
  normal.assign(mesh.vertexCount(), Vec3::Zero());
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Vec3 n = areaNormal(mesh, f);
    for (int v : mesh.faces[f]) normal[v] += n;
  }
  for (int r = 0; r < rings; ++r) {
    scratch = normal;
    for (int v = 0; v < topo.vertexCount(); ++v)
      for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) normal[v] += scratch[topo.ringVertex(k)];
  }
  for (Vec3& n : normal) {
    const double len = n.norm();
    n = len > 0 ? Vec3(n / len) : Vec3::Zero();
  }
}

}  // namespace

void relaxTangentially(TriMesh& mesh, const std::vector<std::uint8_t>& free, int iterations, double damping) {
  const Topology topo(mesh.vertexCount(), mesh.faces);
  Geometry geo;
  std::vector<Vec3> next;
  for (int it = 0; it < iterations; ++it) {
    computeGeometry(topo, mesh.positions, VertexArea::Mixed, geo);
    relaxPass(topo, free, geo.vertexNormal, damping, mesh.positions, next);
  }
}

bool isTangled(const TriMesh& mesh, const std::vector<std::uint8_t>& faceFlags, double angleDegrees) {
  const std::vector<std::uint8_t> flags = flaggedOrAll(mesh, faceFlags);
  if (smallestAngleDegrees(mesh, flags) < angleDegrees) return true;
  std::vector<Vec3> cornerSum(mesh.vertexCount(), Vec3::Zero()), faceNormal(mesh.faces.size());
  for (int f = 0; f < mesh.faceCount(); ++f) {
    faceNormal[f] = areaNormal(mesh, f);
    for (int v : mesh.faces[f]) cornerSum[v] += faceNormal[f];
  }
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (!flags[f]) continue;
    const auto& t = mesh.faces[f];
    if (faceNormal[f].dot(cornerSum[t[0]] + cornerSum[t[1]] + cornerSum[t[2]]) < 0) return true;
  }
  return false;
}

int untangle(TriMesh& mesh, const std::vector<std::uint8_t>& free, const std::vector<std::uint8_t>& faceFlags,
             int maxIterations) {
  // Ten passes must raise the smallest angle by this factor, or the mesh is as even as this rule
  // makes it (a 32×16 UV sphere jittered by half an edge: 0.26° → 10.5° in 20 passes, then flat).
  constexpr int kWindow = 10;
  constexpr double kProgress = 1.01;
  constexpr int kNormalRings = 2;
  const std::vector<std::uint8_t> flags = flaggedOrAll(mesh, faceFlags);
  const Topology topo(mesh.vertexCount(), mesh.faces);
  std::vector<Vec3> normal, scratch, next;
  double checked = smallestAngleDegrees(mesh, flags);
  int it = 0;
  while (it < maxIterations) {
    smoothedNormals(topo, mesh, kNormalRings, normal, scratch);
    relaxPass(topo, free, normal, 0.5, mesh.positions, next);
    if (++it % kWindow != 0) continue;
    const double angle = smallestAngleDegrees(mesh, flags);
    if (angle < kProgress * checked) break;
    checked = angle;
  }
  return it;
}

}  // namespace elastica
