// Dynamic connectivity, the light way: flip edges that are not Delaunay (the two angles opposite
// the edge sum to more than π, so its cotangent weight is negative) inside the moving region.
// Positions never change, so fixed vertices stay bit for bit; only faces among moving vertices are
// rewritten (in place: each flip reuses the indices of the two faces it replaces).
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Flips non-Delaunay edges whose four vertices are all `movable` (one byte per vertex), as long as
/// the two new triangles keep the orientation of the old pair and the new edge does not exist yet.
/// Repeats up to `maxPasses` passes. Returns the number of flips.
int flipToDelaunay(TriMesh& mesh, const std::vector<std::uint8_t>& movable, int maxPasses = 5);

}  // namespace elastica
