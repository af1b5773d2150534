// SPDX-License-Identifier: GPL-3.0-or-later
// The total curvature (thin-plate bending) energy the elastica flow minimises, paper eq. 1.1:
//   E = ∫ (k1² + k2²) dA = ∫ (4H² − 2K) dA,  discretely  E = Σ_i (4 H_i² − 2 K_i) A_i
// over interior, regular (and, if a mask is given, active) vertices, with the raw H.
// For closed surfaces E = 4W − 4πχ with W = ∫H² (Willmore): a sphere has E = 8π.
#pragma once

#include <elastica/curvature.h>

#include <cstdint>
#include <vector>

namespace elastica {

double totalCurvatureEnergy(const Topology& topo, const Geometry& geo, const Curvature& c,
                            const std::vector<std::uint8_t>* active = nullptr);

/// Vertex i's term (4 H_i² − 2 K_i) A_i of totalCurvatureEnergy, 0 where the sum skips the vertex
/// (a boundary or irregular vertex; the active mask is the caller's).
inline double vertexCurvatureEnergy(const Topology& topo, const Geometry& geo, const Curvature& c, int i) {
  if (!geo.isRegular(i) || topo.isBoundaryVertex(i)) return 0;
  return (4 * c.H[i] * c.H[i] - 2 * c.K[i]) * geo.vertexArea[i];
}

}  // namespace elastica
