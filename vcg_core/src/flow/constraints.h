// SPDX-License-Identifier: GPL-3.0-or-later
// Which vertices move. The flow's speed contains Δ_B H, which at a vertex needs H on its
// neighbours, which needs their neighbours: so a moving region is surrounded by two fixed rings
// (ring 1: fixed neighbours of moving vertices, where H is still evaluated; ring 2: theirs). With
// them, position and tangent plane are clamped where the moving region meets the fixed one (G¹).
#pragma once

#include <elastica/flow.h>
#include <elastica/topology.h>

#include <cstdint>
#include <vector>

namespace elastica {

struct VertexRoles {
  std::vector<std::uint8_t> free;        ///< moves with the flow
  std::vector<std::uint8_t> sliding;     ///< boundary vertex sliding along the boundary (Slide mode)
  std::vector<std::uint8_t> active;      ///< free or ring 1: where energy and λ are measured
  std::vector<std::uint8_t> activeFace;  ///< faces with a moving vertex: where A_min is taken
  int freeCount = 0;
  int slidingCount = 0;
};

/// Assigns roles. A vertex is *movable* if all its faces are selected (MeshLab's
/// VertexFromFaceStrict; every face when `faceSelected` is null or empty). Movable vertices are
/// free unless they are on the mesh boundary or next to it (Fixed mode: the boundary row and its
/// neighbours are the two fixed rings), or on the boundary (Slide mode: those slide instead).
VertexRoles assignRoles(const Topology& topo, const std::vector<std::uint8_t>* faceSelected, BoundaryMode mode);

}  // namespace elastica
