// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/incomplete_cholesky_cg.h"
#include "flow/conjugate_gradients.h"

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>

namespace elastica {
namespace {

// A column whose residual, after this many iterations, is more than kBehind times above the
// geometric decay that would reach the tolerance within the budget stops there: it would not make
// it, and the iterations left would be wasted before the caller's factorisation (a 711,420-vertex
// noisy scan needed 159 iterations a column, 0.1–0.3 s each).
constexpr int kJudgeAfter = 10;
constexpr double kBehind = 10;

}  // namespace

struct IncompleteCholeskyCg::Impl {
  Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>> factor;
  const Eigen::SparseMatrix<double>* A = nullptr;
  bool ready = false;

  // Conjugate gradients on one column from x = 0, stopping on the true residual ‖A x − b‖; the
  // iterations taken, or −1.
  int column(const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance, int maxIterations) const {
    const double scale = b.norm(), target = tolerance * scale;
    auto rule = [&](Eigen::Index, int k, const auto& r, double) {
      const double residual = r.norm();
      if (!std::isfinite(residual)) return CgVerdict::GiveUp;
      if (residual <= target) return CgVerdict::Converged;
      if (k >= kJudgeAfter && residual > kBehind * scale * std::pow(tolerance, double(k) / maxIterations))
        return CgVerdict::GiveUp;
      return CgVerdict::Continue;
    };
    return conjugateGradients(
        b, x, [&](const Eigen::VectorXd& p, Eigen::VectorXd& Ap) { Ap.noalias() = *A * p; },
        [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = factor.solve(r); }, rule, maxIterations);
  }
};

IncompleteCholeskyCg::IncompleteCholeskyCg() : impl_(std::make_unique<Impl>()) {}
IncompleteCholeskyCg::~IncompleteCholeskyCg() = default;

bool IncompleteCholeskyCg::compute(const Eigen::SparseMatrix<double>& A) {
  impl_->A = &A;
  impl_->factor.compute(A);
  return impl_->ready = impl_->factor.info() == Eigen::Success;
}

int IncompleteCholeskyCg::solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X, double tolerance, int maxIterations) {
  if (!impl_->ready) return -1;
  X.resize(B.rows(), B.cols());
  Eigen::VectorXd x;
  int most = 0;
  for (Eigen::Index c = 0; c < B.cols(); ++c) {
    const int iterations = impl_->column(B.col(c), x, tolerance, maxIterations);
    if (iterations < 0) return -1;
    X.col(c) = x;
    most = std::max(most, iterations);
  }
  return most;
}

}  // namespace elastica
