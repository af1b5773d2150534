// Evening out a patch's triangles without changing its shape: each free vertex moves toward the
// centroid of its neighbours, within its tangent plane. A curvature flow moves vertices along their
// normals only, so the triangle shapes it starts from are, up to its weak drift, the ones it ends
// with; relaxing first keeps a filled patch free of slivers.
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// `iterations` Jacobi passes: p_i ← p_i + damping · Π_i(c_i − p_i) for the vertices flagged in
/// `free`, c_i the mean of the neighbours and Π_i the projection onto the tangent plane at i.
/// Vertices not flagged never move.
void relaxTangentially(TriMesh& mesh, const std::vector<std::uint8_t>& free, int iterations = 10,
                       double damping = 0.5);

}  // namespace elastica
