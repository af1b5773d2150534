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

}  // namespace elastica
