// SPDX-License-Identifier: GPL-3.0-or-later
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

/// Subdivides only the region of `mesh` flagged in `faceFlags` (one byte per face): each flagged
/// face splits 1-to-4 at its edge midpoints, and so that the mesh stays conforming each unflagged
/// face splits at the midpoints of those of its edges that it shares with the region: into 2
/// (one such edge), 3 (two; the quad cut along its shorter diagonal) or 4 (three). No vertex
/// moves and every other face is kept as it was, at its index. Old vertices keep their indices;
/// midpoints are appended; a split face's first child takes its index, the other children are
/// appended. `faceFlags` is updated: the children of flagged faces are flagged, no other face is.
/// With every face flagged the result is subdivideMidpoint's, faces in another order.
void subdivideMidpointRegion(TriMesh& mesh, std::vector<std::uint8_t>& faceFlags);

/// Loop subdivision of the flagged faces: their faces and vertices as subdivideMidpointRegion makes
/// them (unflagged faces split only along edges they share with flagged ones), but a vertex all of
/// whose faces are flagged (off the border) and an edge vertex whose two faces are flagged move to
/// Loop's masks (as subdivideLoop's); every other vertex stays where it was, every other edge vertex
/// at its midpoint. A smooth region refined inside a mesh stays smooth, and nothing outside the
/// flagged faces' vertices moves. `faceFlags` is updated as subdivideMidpointRegion updates it.
/// @throws InvalidInputError as Topology on a non-manifold mesh, or on a flag count other than the faces'.
void subdivideLoopRegion(TriMesh& mesh, std::vector<std::uint8_t>& faceFlags);

/// Loop subdivision of a closed mesh (Loop 1987, with Warren's weights β = 3/(8n), 3/16 at valence
/// 3): the same 1-to-4 faces as subdivideMidpoint (old vertices keep their indices, edge vertices
/// are appended), but every vertex moves to the scheme's smoothing mask, so a smooth coarse
/// surface stays smooth instead of keeping its facets as creases. Throws InvalidInputError on a
/// mesh with a border.
void subdivideLoop(TriMesh& mesh);

}  // namespace elastica
