// SPDX-License-Identifier: GPL-3.0-or-later
// Conjugate gradients preconditioned by an incomplete Cholesky factorisation (Eigen's, on the
// matrix's own pattern: no fill, AMD ordering, diagonal scaling, shifted until it factors). For a
// matrix close to its diagonal, as a fairing amount's M + τ/2 · C M⁻¹ C is on a well-shaped mesh,
// a few iterations solve it to rounding at a small part of a direct factorisation's cost and
// memory; near slivers the same matrix is far from its diagonal and the iterations do not reach
// the tolerance: solve() says so, and the caller factorises (flow/spd_solver.h).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace elastica {

class IncompleteCholeskyCg {
 public:
  IncompleteCholeskyCg();
  ~IncompleteCholeskyCg();
  IncompleteCholeskyCg(const IncompleteCholeskyCg&) = delete;
  IncompleteCholeskyCg& operator=(const IncompleteCholeskyCg&) = delete;

  /// Orders and factorises `A` incompletely (symmetric, both triangles stored: the products read
  /// all of it). False if the factorisation failed; `A` must outlive the solves.
  bool compute(const Eigen::SparseMatrix<double>& A);
  /// Solves A X = B column by column, x from 0, until ‖A x − b‖ ≤ tolerance · ‖b‖ in every column.
  /// Returns the most iterations a column took, or −1 if a column did not reach the tolerance
  /// within `maxIterations`, or fell so far behind the pace that would that it was given up early
  /// (X is then not to be used; the columns after it are not tried).
  int solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X, double tolerance, int maxIterations);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace elastica
