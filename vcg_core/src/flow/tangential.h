// SPDX-License-Identifier: GPL-3.0-or-later
// Umbrella operators: the tangential drift that keeps triangles even (paper eq. 2.5) and the
// equal-weight bi-umbrella of the bilaplacian comparison flow (paper §3).
#pragma once

#include <elastica/geometry.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Scratch storage of tangentialDrift, sized on first use and reused without allocating.
struct DriftScratch {
  std::vector<double> weight;  ///< per edge: (a⁻ + a⁺)/|P_j − P_i|
  std::vector<Vec3> u;         ///< U(P)
};

/// T = −(U² − (U²·N)N) at `moving` vertices (zero elsewhere), where U is the paper's
/// area-weighted umbrella
///   U(P)_i = 1/(2 A_i n_i) Σ_j (a⁻_ij + a⁺_ij) (P_j − P_i)/|P_j − P_i|
/// (a± the triangles on edge ij, A_i the one-ring area, n_i the valence), U = 0 at vertices that
/// do not move, and U² = U(U(P)). Lengths and areas are those of `g`, computed from `p`.
void tangentialDrift(const Topology& topo, const Geometry& g, const std::vector<Vec3>& p,
                     const std::vector<std::uint8_t>& moving, DriftScratch& scratch, std::vector<Vec3>& t);

/// U0²(P) at `moving` vertices (zero elsewhere), U0(P)_i = (1/n_i) Σ_j (P_j − P_i) the
/// equal-weight umbrella, evaluated at every interior vertex (zero on the boundary, where it is
/// one-sided). `u0` is scratch storage.
void uniformBiUmbrella(const Topology& topo, const std::vector<Vec3>& p, const std::vector<std::uint8_t>& moving,
                       std::vector<Vec3>& u0, std::vector<Vec3>& out);

}  // namespace elastica
