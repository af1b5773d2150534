// SPDX-License-Identifier: GPL-3.0-or-later
// Distances between two triangle soups, sampled: how far a restored patch is from the surface that
// was cut away (and back), for the restoration benchmark.
#pragma once

#include <elastica/types.h>

#include <vector>

namespace elastica::bench {

struct DistanceStats {
  double rms = 0, max = 0;
};

/// Distance from points sampled on the faces of `a` (a barycentric grid of `perEdge` steps a side:
/// (`perEdge` + 1)(`perEdge` + 2)/2 points per face, corners and edges included) to the nearest face
/// of `b` (exact nearest face, found in a bounding-box tree over `b`'s faces).
DistanceStats sampledDistance(const TriMesh& a, const TriMesh& b, int perEdge = 6);

/// The faces of `m` flagged in `keep`, with their vertices, as a standalone mesh.
TriMesh facesOf(const TriMesh& m, const std::vector<std::uint8_t>& keep);

}  // namespace elastica::bench
