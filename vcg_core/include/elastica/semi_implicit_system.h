// The linear system of one semi-implicit step (DESIGN.md §4): to leading order
// F(P + δN) ≈ F − ½ Δ_B² δ, so the normal displacement δ of the free vertices f solves
//   (M_ff + τ/2 · C_fa M_aa⁻¹ C_af) δ_f = τ M_ff F_f,
// with a = free ∪ ring 1, C the cotangent matrix and M the vertex areas. SPD; about 19 nonzeros per
// row (the two-ring stencil).
#pragma once

#include <elastica/geometry.h>
#include <elastica/topology.h>

#include <Eigen/SparseCore>

#include <cstdint>
#include <vector>

namespace elastica {

/// Assembles the matrix into `K` (n × n, n = number of rows in `freeIndex`) and the right-hand
/// side into `rhs`. `freeIndex[v]` is the row of free vertex v or −1; `active` marks free ∪ ring 1;
/// `speed` is F per vertex. `triplets` is scratch storage (kept to avoid reallocating).
void assembleSemiImplicitSystem(const Topology& topo, const Geometry& geo, const std::vector<std::uint8_t>& active,
                                const std::vector<int>& freeIndex, int n, const std::vector<double>& speed, double tau,
                                std::vector<Eigen::Triplet<double>>& triplets, Eigen::SparseMatrix<double>& K,
                                Eigen::VectorXd& rhs);

}  // namespace elastica
