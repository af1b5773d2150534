// SPDX-License-Identifier: GPL-3.0-or-later
// Limited-memory BFGS on top of a preconditioner (Nocedal's two-loop recursion): the last few
// accepted steps s and the changes y of the gradient across them correct the preconditioner's
// model of the inverse Hessian H₀ along the directions the flow actually took. Used by
// VectorIntegrator::quasiNewton, where H₀ is the step's own solve (τ/4 · K⁻¹).
#pragma once

#include <Eigen/Core>

#include <deque>
#include <functional>
#include <vector>

namespace elastica {

class SecantPairs {
 public:
  explicit SecantPairs(int capacity) : capacity_(capacity) {}
  /// Adds the pair (s, y) (one row per unknown, all columns alike) if its curvature s·y is positive
  /// relative to |s||y| (kMinCurvature); the oldest pair goes beyond the capacity. A pair with
  /// s·y ≤ 0 would make the update indefinite and the direction possibly not a descent one.
  bool add(const Eigen::MatrixXd& s, const Eigen::MatrixXd& y);
  void clear() { pairs_.clear(); }
  bool empty() const { return pairs_.empty(); }
  int size() const { return static_cast<int>(pairs_.size()); }
  /// H·g, H the L-BFGS inverse Hessian from H₀ (`applyH0(q, out)`: out = H₀ q; false if it fails)
  /// and the pairs. With no pair it is H₀ g. False if applyH0 fails.
  bool apply(const Eigen::MatrixXd& g, const std::function<bool(const Eigen::MatrixXd&, Eigen::MatrixXd&)>& applyH0,
             Eigen::MatrixXd& hg) const;

 private:
  struct Pair {
    Eigen::MatrixXd s, y;
    double rho;  // 1 / s·y
  };
  int capacity_;
  std::deque<Pair> pairs_;
  mutable std::vector<double> alpha_;
};

/// Σ a_ij b_ij over all entries, in a fixed order (the bits do not depend on the thread count).
double frobeniusDot(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

}  // namespace elastica
