// Linear 1-to-4 subdivision: every triangle splits into four at its edge midpoints; no existing
// vertex moves, so the shape is unchanged at the moment of subdividing (the paper's coarse-to-fine
// acceleration: flow near steady state, subdivide, flow again).
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Subdivides `mesh` in place. Old vertices keep their indices; midpoints are appended. If
/// `faceFlags` is given (one byte per face), each child face inherits its parent's flag.
void subdivideMidpoint(TriMesh& mesh, std::vector<std::uint8_t>* faceFlags = nullptr);

}  // namespace elastica
