// Raising a patch's smallest angle where remeshing leaves it low: on the ring of faces that touch
// the hole's border. Remeshing treats border edges as fixed and aims at valence 6 and edge length;
// what it leaves is a border face whose apex sits too close to, or too far along, its border edge
// (7.2° on a 290-edge hole cut in a 36k-vertex scan). Here every patch vertex is placed, within its
// tangent plane, where the smallest angle of its own faces is largest — among its current place,
// the centroid of its neighbours and, for each border edge it faces, the apex of the equilateral
// triangle on that edge — and patch edges are flipped where that raises the smaller angle of their
// two faces (faces touching the border included; edges of the border itself and faces outside the
// patch never change).
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Improves the smallest angles of the faces flagged in `patchFace` by moving the vertices from
/// `firstNew` on (tangentially) and flipping edges between two patch faces. No face turns over;
/// vertices before `firstNew`, faces outside the patch and the number and flags of faces stay.
/// Returns the number of moves and flips made.
int improvePatchAngles(TriMesh& mesh, const std::vector<std::uint8_t>& patchFace, int firstNew, int passes = 8);

}  // namespace elastica
