// SPDX-License-Identifier: GPL-3.0-or-later
// Triangulating a hole: Liepa's minimum-weight triangulation ("Filling Holes in Meshes", SGP 2003),
// the one CGAL uses. Among all triangulations of the boundary polygon it picks the one whose
// largest dihedral angle (between neighbouring triangles, and with the mesh faces around the hole)
// is smallest, then the smallest area: the fill follows the surrounding surface's tangent planes
// and never doubles back on itself the way greedy ear cutting can.
#pragma once

#include <elastica/types.h>
#include "restoration/hole_boundary.h"

#include <functional>
#include <optional>
#include <vector>

namespace elastica {

/// Triangulates `loop` over `positions` without adding vertices. A diagonal for which
/// `edgeExists(a, b)` (two mesh vertices already joined) is never used: it would make that edge
/// non-manifold; nor is a triangle without area. The triangles are oriented like the mesh around
/// the hole. O(n³) time and O(n²) memory up to 100 border edges; longer borders are cut by chords
/// into pieces of at most 100 (O(n²) for the chord search, then O(100²·n)), searched one by one.
/// Returns nothing if the loop is pinched or no triangulation avoids the existing edges and
/// degenerate triangles.
std::optional<std::vector<Face>> triangulateHole(const std::vector<Vec3>& positions, const HoleLoop& loop,
                                                 const std::function<bool(int, int)>& edgeExists);

}  // namespace elastica
