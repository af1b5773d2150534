// SPDX-License-Identifier: GPL-3.0-or-later
#include "restoration/rim_rule.h"

#include <cmath>
#include <numeric>

namespace elastica {
namespace {

constexpr double kRimAreaRatio = 0.25;

// The connected pieces of `mesh` (by shared vertices): a union-find over the vertices.
class Pieces {
 public:
  explicit Pieces(const TriMesh& mesh) : parent_(mesh.positions.size()) {
    std::iota(parent_.begin(), parent_.end(), 0);
    for (const Face& t : mesh.faces) {
      join(t[0], t[1]);
      join(t[1], t[2]);
    }
  }
  int find(int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }

 private:
  void join(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  std::vector<int> parent_;
};

double vectorArea(const std::vector<Vec3>& positions, const std::vector<int>& vertices) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < vertices.size(); ++i)
    sum += positions[vertices[i]].cross(positions[vertices[(i + 1) % vertices.size()]]);
  return 0.5 * sum.norm();
}

}  // namespace

double geodesicTurning(const HoleLoop& loop, const std::function<double(int)>& meshAngle) {
  double turning = 0;
  for (int v : loop.vertices) turning += M_PI - meshAngle(v);
  return turning;
}

std::vector<RimMeasure> classifyRims(const TriMesh& mesh, const std::vector<HoleLoop>& loops,
                                     const std::function<double(int)>& meshAngle) {
  std::vector<RimMeasure> out(loops.size());
  bool anyOutline = false;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    out[l].turning = geodesicTurning(loops[l], meshAngle);
    anyOutline = anyOutline || out[l].turning > 0;
  }
  if (!anyOutline) return out;
  Pieces pieces(mesh);
  std::vector<double> area(mesh.positions.size(), 0);  // by the piece's root vertex
  for (const Face& t : mesh.faces) {
    const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    area[pieces.find(t[0])] += 0.5 * (b - a).cross(c - a).norm();
  }
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (out[l].turning <= 0) continue;
    const double pieceArea = area[pieces.find(loops[l].vertices.front())];
    out[l].areaRatio = pieceArea > 0 ? vectorArea(mesh.positions, loops[l].vertices) / pieceArea : 0;
    out[l].rim = out[l].areaRatio >= kRimAreaRatio;
  }
  return out;
}

}  // namespace elastica
