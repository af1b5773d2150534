// SPDX-License-Identifier: GPL-3.0-or-later
// The input surface of a remeshing that must not move it (a CAD tessellation's, issue 40 item 3):
// closest points on its faces and on its sharp edges, so that a remesher can put every vertex it
// moves back on the surface and keep the part's creases where they are (mesh/patch_remeshing.h:
// PatchRemeshingOptions::surface).
#pragma once

#include "mesh/face_tree.h"

#include <elastica/types.h>

#include <utility>
#include <vector>

namespace elastica {

/// The edges of `mesh` with two faces whose normals differ by more than `angleDegrees` (the
/// dihedral's supplement: 90° on a box's edges), each once as (smaller, larger), in increasing order.
std::vector<std::pair<int, int>> sharpEdges(const TriMesh& mesh, double angleDegrees);

/// The closest point on segment (a, b) to p (a if the segment has no length).
Vec3 closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b);

/// The closest point on triangle (a, b, c) to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// A copy of a surface with its sharp edges (sharpEdges at `featureAngleDegrees`), and trees over
/// both for closest-point queries. The queries are const and may run in parallel.
class SurfaceProjector {
 public:
  SurfaceProjector(const TriMesh& surface, double featureAngleDegrees);

  /// The closest point to p on a face whose normal makes less than 90° with `normal` (any face if
  /// `normal` is zero): a thin wall's other side, turned away, is never the one found. False if no
  /// face qualifies.
  bool project(const Vec3& p, const Vec3& normal, Vec3& onSurface) const;
  /// The closest point to p on a sharp edge. False if the surface has none.
  bool projectOnSharpEdge(const Vec3& p, Vec3& onEdge) const;

  double featureAngleDegrees() const { return featureAngle_; }
  const TriMesh& surface() const { return surface_; }
  const std::vector<std::pair<int, int>>& edges() const { return sharp_; }

 private:
  TriMesh surface_;
  double featureAngle_;
  std::vector<Vec3> normal_;  // unit face normals (zero for a degenerate face)
  std::vector<std::pair<int, int>> sharp_;
  BoxTree faces_, segments_;
};

}  // namespace elastica
