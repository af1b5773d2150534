// SPDX-License-Identifier: GPL-3.0-or-later
// Dynamic connectivity, the light way: flip edges that are not Delaunay (the two angles opposite
// the edge sum to more than π, so its cotangent weight is negative) inside the moving region.
// Positions never change, so fixed vertices stay bit for bit; only faces among moving vertices are
// rewritten (in place: each flip reuses the indices of the two faces it replaces).
#pragma once

#include <elastica/topology.h>
#include <elastica/types.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace elastica {

/// Flips non-Delaunay edges whose four vertices are all `movable` (one byte per vertex), as long as
/// the two new triangles keep the orientation of the old pair and the new edge does not exist yet.
/// Repeats up to `maxPasses` passes. Returns the number of flips.
int flipToDelaunay(TriMesh& mesh, const std::vector<std::uint8_t>& movable, int maxPasses = 5);
/// The same flips, reading `current`, the mesh's adjacency before them (a flow state keeps one),
/// instead of building it: after most steps of a region's flow the flips rebuilt the piece's
/// topology twice, once here. A `current` that is null or not the mesh's (other faces) is not read.
int flipToDelaunay(TriMesh& mesh, const Topology* current, const std::vector<std::uint8_t>& movable, int maxPasses = 5);

/// The general form: flips non-Delaunay edges where `allowed(a, b, c, d, f0, f1)` is true — edge
/// (a, b) shared by faces f0 = (a, b, c) and f1 = (b, a, d), to become edge (c, d) — as long as the
/// orientation is kept and (c, d) is not an edge yet. Up to `maxPasses` passes; returns the flips.
using FlipFilter = std::function<bool(int a, int b, int c, int d, int f0, int f1)>;
int flipToDelaunay(TriMesh& mesh, const FlipFilter& allowed, int maxPasses);

}  // namespace elastica
