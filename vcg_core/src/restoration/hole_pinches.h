// SPDX-License-Identifier: GPL-3.0-or-later
// Hole borders that pass twice through one point. A vertex where two fans of faces meet only at
// a point is stored as two copies at one position (the reader splits such "bow-tie" vertices, and
// files often store them so); the hole between the fans then runs through both copies. Filled as
// one polygon, that border needs a triangle joining the copies, with no area. Instead the copies
// are welded back into one vertex and the border split there into loops that each pass once
// through the point: filling them joins the fans and makes the vertex an ordinary one.
#pragma once

#include <elastica/hole_filling.h>
#include <elastica/types.h>
#include "restoration/hole_boundary.h"

#include <functional>
#include <vector>

namespace elastica {

struct PinchSplit {
  std::vector<HoleLoop> loops;   ///< simple loops (no two vertices at one position)
  std::vector<PinchWeld> welds;  ///< in the order they were made
};

/// Splits `loop` at every pair of its vertices with bit-identical positions that `weld(kept,
/// removed)` agrees to merge (the caller merges them in its mesh and returns true, or returns false
/// where merging would make an edge non-manifold; the loop is then not split there). A loop part
/// of two edges (a slit between the copies) closes by the weld alone and is not returned.
PinchSplit splitAtPinches(const HoleLoop& loop, const std::vector<Vec3>& positions,
                          const std::function<bool(int kept, int removed)>& weld);

}  // namespace elastica
