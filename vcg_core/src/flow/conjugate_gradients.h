// SPDX-License-Identifier: GPL-3.0-or-later
// Preconditioned conjugate gradients on the columns of a dense block (a vector is one column), in
// step: one product with the matrix and one application of the preconditioner per iteration for
// all columns, so a factorisation's solve passes over its factor once for all of them. The
// stopping rule is the caller's: SpdSolver stops on the preconditioned residual, IncompleteCholeskyCg
// on the true one, and gives up on a column that falls behind its pace.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace elastica {

/// What a stopping rule says about a column after an iteration.
enum class CgVerdict { Continue, Converged, GiveUp };

/// Solves A X = B from X = 0. `product(p, Ap)` sets Ap = A p, `precondition(r, z)` sets z ≈ A⁻¹ r;
/// `rule(c, k, r, rz)` judges column c after k iterations (k = 0: the start) from its residual r
/// and r·z. A column that converges stops (its direction is zeroed: A·0 = 0 adds nothing). Returns
/// the iterations the slowest column took, or −1 if a column gave up, did not converge within
/// `maxIterations`, or met a direction of non-positive curvature or a non-finite value (X is then
/// not to be used).
template <class Dense, class Product, class Precondition, class Rule>
int conjugateGradients(const Dense& b, Dense& x, Product&& product, Precondition&& precondition, Rule&& rule,
                       int maxIterations) {
  const Eigen::Index columns = b.cols();
  x.setZero(b.rows(), columns);
  Dense r = b, z, p, Ap;
  precondition(r, z);
  Eigen::VectorXd rz(columns);
  std::vector<bool> done(columns, false);
  for (Eigen::Index c = 0; c < columns; ++c) {
    rz[c] = r.col(c).dot(z.col(c));
    const CgVerdict verdict = rule(c, 0, r.col(c), rz[c]);
    if (verdict == CgVerdict::GiveUp) return -1;
    done[c] = verdict == CgVerdict::Converged;
  }
  auto allDone = [&] { return std::all_of(done.begin(), done.end(), [](bool d) { return d; }); };
  p = z;
  for (Eigen::Index c = 0; c < columns; ++c)
    if (done[c]) p.col(c).setZero();
  for (int k = 1; k <= maxIterations; ++k) {
    if (allDone()) return k - 1;
    product(p, Ap);
    for (Eigen::Index c = 0; c < columns; ++c) {
      if (done[c]) continue;
      const double curvature = p.col(c).dot(Ap.col(c));
      if (!(curvature > 0)) return -1;
      const double alpha = rz[c] / curvature;
      x.col(c) += alpha * p.col(c);
      r.col(c) -= alpha * Ap.col(c);
    }
    precondition(r, z);
    for (Eigen::Index c = 0; c < columns; ++c) {
      if (done[c]) continue;
      const double next = r.col(c).dot(z.col(c));
      if (!std::isfinite(next)) return -1;
      const CgVerdict verdict = rule(c, k, r.col(c), next);
      if (verdict == CgVerdict::GiveUp) return -1;
      if (verdict == CgVerdict::Converged) {
        done[c] = true;
        p.col(c).setZero();
        continue;
      }
      p.col(c) = z.col(c) + (next / rz[c]) * p.col(c);
      rz[c] = next;
    }
  }
  return allDone() ? maxIterations : -1;
}

}  // namespace elastica
