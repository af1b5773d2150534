// SPDX-License-Identifier: GPL-3.0-or-later
// Raising a patch's smallest angle where remeshing leaves it low: on the ring of faces that touch
// the hole's border. Remeshing treats border edges as fixed and aims at valence 6 and edge length;
// what it leaves is a border face whose apex sits too close to, or too far along, its border edge
// (7.2° on a 290-edge hole cut in a 36k-vertex scan). Here every patch vertex is placed, within its
// tangent plane, where the smallest angle of its own faces is largest — among its current place,
// the centroid of its neighbours and, for each border edge it faces, the apex of the equilateral
// triangle on that edge — and patch edges are flipped where that raises the smaller angle of their
// two faces (faces touching the border included; edges of the border itself and faces outside the
// patch never change). An ear (three border corners) is split first: its corners cannot move.
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Improves the smallest angles of the faces flagged in `patchFace` by splitting ears (patch faces
/// with all three corners on the border, below 25°: their inner edge, at its midpoint), moving
/// the vertices from `firstNew` on (tangentially) and flipping edges between two patch faces. No
/// face turns over; vertices before `firstNew` and faces outside the patch stay as they are. Split
/// points are appended (`sigma` gets the mean of the edge's ends), their faces appended flagged.
/// Vertices whose faces all have angles of `goodEnoughDegrees` or more stay where they are (35°
/// by default: the 25° of issue 15 with a margin, for a patch about to be flowed).
/// `finishing`: the last pass on a flowed patch; the apexes of border edges are then also placed
/// by a fine compass search (the best place between two border edges of unequal length).
/// Returns the number of splits, moves and flips made.
int improvePatchAngles(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
                       double goodEnoughDegrees = 35, int passes = 8, bool finishing = false);

}  // namespace elastica
