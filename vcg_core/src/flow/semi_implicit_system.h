// SPDX-License-Identifier: GPL-3.0-or-later
// The linear system of one semi-implicit step: to leading order
// F(P + δN) ≈ F − ½ Δ_B² δ, so the normal displacement δ of the free vertices f solves
//   (M_ff + τ/2 · C_fa M_aa⁻¹ C_af) δ_f = τ M_ff F_f,
// with a = free ∪ ring 1, C the cotangent matrix and M the vertex areas. SPD; about 19 nonzeros per
// row (the two-ring stencil).
#pragma once

#include <elastica/geometry.h>
#include <elastica/topology.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstdint>
#include <array>
#include <utility>
#include <vector>

namespace elastica {

class SemiImplicitSystem {
 public:
  /// Assembles the matrix and the right-hand side for step `tau`. `freeIndex[v]` is the row of
  /// free vertex v or −1 (`n` rows); `active` marks free ∪ ring 1; `speed` is F per vertex. The
  /// sparsity pattern, and where each product C_ia C_ib / A_i lands in it, are worked out on the
  /// first call and reused (no allocation, no sorting) until reset().
  void assemble(const Topology& topo, const Geometry& geo, const std::vector<std::uint8_t>& active,
                const std::vector<int>& freeIndex, int n, const std::vector<double>& speed, double tau);
  /// The matrix alone, in general form: mass · M_ff + scale · C_fa M_aa⁻¹ C_af, with C_ij from
  /// `edgeWeight` (per edge of `topo`) and M from `vertexArea` (a vertex without area adds no
  /// product). assemble() is (1, τ/2) with the geometry's weights; the bi-Laplace start
  /// (restoration/biharmonic_embedding.cpp) is (0, 1). Leaves the right-hand side as it was.
  void assembleMatrix(const Topology& topo, const std::vector<double>& edgeWeight, const std::vector<double>& vertexArea,
                      const std::vector<std::uint8_t>& active, const std::vector<int>& freeIndex, int n, double mass,
                      double scale);
  /// Adds scale · Σ_edges w_e (x_i − x_j)² to the assembled matrix: scale · w_e on the diagonals
  /// of the edge's free ends and −scale · w_e between them (a weighted graph Laplacian, positive
  /// semidefinite for w ≥ 0), `edgeWeight` per edge of `topo`. Call after assembleMatrix().
  void addEdgeLaplacian(const Topology& topo, const std::vector<double>& edgeWeight, const std::vector<int>& freeIndex,
                        double scale);
  /// Multiplies the assembled matrix's diagonal entry of `row` by `factor` (Marquardt's damping of
  /// one unknown). Call after assembleMatrix().
  void scaleDiagonal(int row, double factor) { K_.coeffRef(row, row) *= factor; }
  /// Forgets the pattern: call when the connectivity or the free vertices change.
  void reset() { patterned_ = false; }
  /// Hands over the assembled matrix and forgets the pattern, for a matrix assembled once: the
  /// system can then be destroyed, with its products' slots (about 50 ints a row on the two-ring).
  Eigen::SparseMatrix<double> takeMatrix() {
    patterned_ = false;
    return std::move(K_);
  }

  const Eigen::SparseMatrix<double>& matrix() const { return K_; }
  const Eigen::VectorXd& rhs() const { return rhs_; }

 private:
  void buildPattern(const Topology& topo, const std::vector<std::uint8_t>& active, const std::vector<int>& freeIndex,
                    int n);

  Eigen::SparseMatrix<double> K_;
  Eigen::VectorXd rhs_;
  std::vector<int> slot_;          // per product, in assembly order: its index in K_'s values
  bool holds(int slot, int row, int column) const;
  int find(int row, int column) const;

  std::vector<int> diagonalSlot_;  // per row
  // Per edge, the slots of (a, b) and (b, a) that addEdgeLaplacian last found (checked at each
  // use): its coeffRef searches, four per edge at every step, were a few percent of a region's run.
  std::vector<std::array<int, 2>> edgeSlot_;
  std::vector<std::pair<int, double>> column_;  // (row, C_ij) of the free vertices around one vertex
  bool patterned_ = false;
};

}  // namespace elastica
