// SPDX-License-Identifier: GPL-3.0-or-later
// Rims and holes: an open scan's outer border (a terrain's edge, a face scan's outline, a lone
// triangle's sides) is not a hole to fill. The rule, per boundary loop:
//   - the loop turns like an outline: its geodesic turning Σ (π − θ_v) over its vertices (θ_v the
//     angle the mesh's faces span at v) is positive. By Gauss–Bonnet a patch closing the loop
//     would carry 2π + that turning of total Gaussian curvature: more than a hemisphere's 2π. A
//     hole cut from a surface turns by about −2π (a flat plug closes it); a flat disc's outline
//     by +2π (only a pillow closes it);
//   - and the loop spans at least a quarter of the area of the piece of mesh it bounds (its
//     vector area ½|Σ p_i × p_{i+1}|), so a tube's end, whose turning is about 0, stays a hole
//     unless the tube is shorter than twice its radius.
// Both at once make a rim. Scale-free and independent of the mesh's density; the fence cases
// are a hemisphere (turning 0) and a sphere missing more than half (a bowl: a rim).
#pragma once

#include <elastica/types.h>
#include "restoration/hole_boundary.h"

#include <functional>
#include <vector>

namespace elastica {

/// What the rule measured of one loop.
struct RimMeasure {
  double turning = 0;    ///< Σ (π − θ_v), radians
  double areaRatio = 0;  ///< the loop's vector area over its piece's area (0 when not measured)
  bool rim = false;
};

/// The loop's geodesic turning; `meshAngle(v)`: the angle the mesh's faces span at v (radians).
double geodesicTurning(const HoleLoop& loop, const std::function<double(int)>& meshAngle);

/// The rule for every loop of `mesh`. The pieces' areas are measured (one pass over the faces
/// and an int and a double per vertex) only when some loop turns like an outline.
std::vector<RimMeasure> classifyRims(const TriMesh& mesh, const std::vector<HoleLoop>& loops,
                                     const std::function<double(int)>& meshAngle);

}  // namespace elastica
