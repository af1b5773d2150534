// SPDX-License-Identifier: GPL-3.0-or-later
// Preconditioned L-BFGS's two-loop recursion (flow/secant_pairs): with no pair it is the
// preconditioner, it satisfies the newest pair's secant equation, it refuses pairs of non-positive
// curvature, and on an ill-conditioned quadratic it needs far fewer steps than the preconditioner
// alone (the plain step of the vector scheme, which crawls in the τ ≫ T tail).
#include "flow/secant_pairs.h"

#include <Eigen/Core>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace elastica;

namespace {

// A diagonal SPD "Hessian" with eigenvalues spread over [1, condition], one row per unknown and
// three columns alike (the integrator's layout: x, y, z of each free vertex).
Eigen::MatrixXd spreadDiagonal(int rows, double condition) {
  Eigen::MatrixXd a(rows, 3);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < 3; ++c) a(r, c) = std::pow(condition, (r + 0.37 * c) / (rows - 1 + 0.74));
  return a;
}

bool identityH0(const Eigen::MatrixXd& q, Eigen::MatrixXd& out) {
  out = q;
  return true;
}

// Steps x ← x − α H g with the exact line search of f = ½ Σ a x², from x = 1, until |g| falls below
// `tolerance` of its start; the pairs (when used) are the steps taken and their gradient changes.
int stepsToSolve(const Eigen::MatrixXd& a, bool usePairs, double tolerance) {
  SecantPairs pairs(5);
  Eigen::MatrixXd x = Eigen::MatrixXd::Ones(a.rows(), 3), g = a.cwiseProduct(x), hg;
  const double start = std::sqrt(frobeniusDot(g, g));
  for (int step = 1; step <= 100000; ++step) {
    if (!pairs.apply(g, identityH0, hg)) return -1;
    const double alpha = frobeniusDot(g, hg) / frobeniusDot(hg, a.cwiseProduct(hg));
    const Eigen::MatrixXd s = -alpha * hg, y = a.cwiseProduct(s);
    x += s;
    g += y;
    if (usePairs) pairs.add(s, y);
    if (std::sqrt(frobeniusDot(g, g)) < tolerance * start) return step;
  }
  return 100000;
}

}  // namespace

TEST(SecantPairs, WithoutPairsItIsThePreconditioner) {
  SecantPairs pairs(5);
  const Eigen::MatrixXd g = Eigen::MatrixXd::Random(7, 3);
  Eigen::MatrixXd hg;
  auto halve = [](const Eigen::MatrixXd& q, Eigen::MatrixXd& out) { out = 0.5 * q; return true; };
  ASSERT_TRUE(pairs.apply(g, halve, hg));
  EXPECT_EQ((hg - 0.5 * g).norm(), 0.0);
}

TEST(SecantPairs, NewestPairsSecantEquationHolds) {
  const Eigen::MatrixXd a = spreadDiagonal(20, 100);
  SecantPairs pairs(3);
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd s(20, 3);
  for (int k = 0; k < 5; ++k) {
    for (int r = 0; r < 20; ++r)
      for (int c = 0; c < 3; ++c) s(r, c) = n01(rng);
    ASSERT_TRUE(pairs.add(s, a.cwiseProduct(s)));
  }
  EXPECT_EQ(pairs.size(), 3);  // the capacity
  Eigen::MatrixXd hy;
  ASSERT_TRUE(pairs.apply(a.cwiseProduct(s), identityH0, hy));
  EXPECT_LT((hy - s).norm(), 1e-10 * s.norm());  // H y = s for the newest pair
  // and H stays positive definite: a descent direction for any gradient
  for (int k = 0; k < 10; ++k) {
    const Eigen::MatrixXd g = Eigen::MatrixXd::Random(20, 3);
    Eigen::MatrixXd hg;
    ASSERT_TRUE(pairs.apply(g, identityH0, hg));
    EXPECT_GT(frobeniusDot(g, hg), 0);
  }
}

TEST(SecantPairs, RefusesPairsWithoutPositiveCurvature) {
  SecantPairs pairs(5);
  const Eigen::MatrixXd s = Eigen::MatrixXd::Ones(4, 3);
  EXPECT_FALSE(pairs.add(s, -s));                            // W concave along s
  EXPECT_FALSE(pairs.add(s, Eigen::MatrixXd::Zero(4, 3)));   // flat
  EXPECT_TRUE(pairs.add(s, 2 * s));
  EXPECT_EQ(pairs.size(), 1);
}

// Measured: condition 10⁴, 60 × 3 unknowns, |g| down by 10⁻⁸: the preconditioner alone (steepest
// descent with exact line searches) takes 42,863 steps, with five pairs 391.
TEST(SecantPairs, OnAnIllConditionedQuadraticFarFewerStepsThanThePreconditioner) {
  const Eigen::MatrixXd a = spreadDiagonal(60, 1e4);
  const int plain = stepsToSolve(a, false, 1e-8), accelerated = stepsToSolve(a, true, 1e-8);
  EXPECT_GT(accelerated, 0);
  EXPECT_LT(10 * accelerated, plain) << "plain " << plain << ", with pairs " << accelerated;
}
