// SPDX-License-Identifier: GPL-3.0-or-later
// An axis-aligned box around points and faces: the broad phase of the embedding guard's crossing
// test (mesh/self_intersection.cpp) and the obstacles a selected region's run may meet
// (flow/region_fairing.cpp).
#pragma once

#include <elastica/types.h>

#include <limits>

namespace elastica {

struct Box {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());  // empty until a point is added
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  /// The boxes share a point (touching counts).
  bool meets(const Box& b) const { return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all(); }
  bool contains(const Box& b) const { return (lo.array() <= b.lo.array()).all() && (b.hi.array() <= hi.array()).all(); }
  Box grown(double d) const { return {lo - Vec3::Constant(d), hi + Vec3::Constant(d)}; }
};

/// The box of face `f` of `mesh`.
inline Box boxOf(const TriMesh& mesh, const Face& f) {
  const Vec3 &a = mesh.positions[f[0]], &b = mesh.positions[f[1]], &c = mesh.positions[f[2]];
  return {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)};
}

}  // namespace elastica
