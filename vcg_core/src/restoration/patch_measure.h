// SPDX-License-Identifier: GPL-3.0-or-later
// What a restoration stage is judged by: the smallest angle of the patch's faces and the total
// curvature energy of the same region, whatever the stage did to the patch's vertices. Stages
// are compared on this (hole_filling.cpp keeps a stage only if it is no worse), and the report
// quotes it, so "before" and "after" always mean the same region.
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

struct PatchMeasure {
  double minAngleDegrees = 180;  ///< over the patch's faces
  /// E = Σ (4H² − 2K) A over the vertices of the patch's faces: its own vertices and its border,
  /// each with its whole fan (the piece of mesh handed in must hold the faces around the border).
  /// With the surroundings fixed, Σ K A over that region is fixed too (Gauss–Bonnet), so what
  /// changes is the bending, 4 ∫H².
  double energy = 0;
};

PatchMeasure measurePatch(const TriMesh& mesh, const std::vector<std::uint8_t>& patchFace);

}  // namespace elastica
