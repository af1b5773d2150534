// SPDX-License-Identifier: GPL-3.0-or-later
// Evening out triangles without changing the surface: each free vertex moves toward the centroid of
// its neighbours, within its tangent plane. A curvature flow that moves vertices along their normals
// keeps, up to its weak drift, the triangle shapes it starts from; relaxing first keeps a filled
// patch free of slivers, and untangles a mesh whose vertices were jittered in 3-D before a flow that
// keeps the connectivity starts on it.
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

/// Whether the faces flagged in `faceFlags` (all faces if empty) are tangled: a corner under
/// `angleDegrees`, or a face turned against the mean normal of its corners (a fold).
bool isTangled(const TriMesh& mesh, const std::vector<std::uint8_t>& faceFlags, double angleDegrees);

/// Untangles a jittered mesh in place: passes of relaxTangentially's rule (damping ½), with each
/// vertex's tangent plane taken from the normals summed over two rings (one ring's normal is as
/// noisy as the jitter), until the smallest angle of the flagged faces stops rising by 1 % over
/// ten passes, or `maxIterations`. Returns the passes made. The surface moves only by what a
/// tangential slide over it costs (second order in the slide); a shape's normal noise stays for the
/// flow to take away.
int untangle(TriMesh& mesh, const std::vector<std::uint8_t>& free, const std::vector<std::uint8_t>& faceFlags,
             int maxIterations = 200);

}  // namespace elastica
