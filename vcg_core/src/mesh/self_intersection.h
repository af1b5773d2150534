// Whether a mesh's faces cross each other: the flow's embedding guard. An output must never
// self-intersect when its input did not, and a handle that pinches shows up as faces crossing
// before it closes. Uniform-grid broad phase over the face boxes (linear in the face count for
// meshes of even triangles), exact-in-double segment–triangle tests for the narrow phase.
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Faces that cross another face, by vcglib's definition (Clean::SelfIntersections): faces
/// sharing no vertex cross if an edge of one passes through the interior of the other; faces
/// sharing one vertex s cross if the segment halfway between s and the opposite edge of one
/// passes through the other (one folded through the other around s); faces sharing an edge never
/// count. Touching and coplanar overlaps (measure zero for a flow) are not counted. With
/// `onlyFace` (one byte per face), pairs where neither face is flagged are skipped: the local test
/// after a step that moved only some faces. Returns the crossing faces' indices, ascending.
std::vector<int> selfIntersectingFaces(const TriMesh& mesh, const std::vector<std::uint8_t>* onlyFace = nullptr);

/// selfIntersectingFaces(mesh, onlyFace) is not empty; stops at the first crossing pair.
bool selfIntersects(const TriMesh& mesh, const std::vector<std::uint8_t>* onlyFace = nullptr);

}  // namespace elastica
