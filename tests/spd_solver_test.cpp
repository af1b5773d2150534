// SPDX-License-Identifier: GPL-3.0-or-later
// The sparse SPD solver of the semi-implicit scheme (flow/spd_solver): each backend solves known
// systems to rounding, refactorises new values on an analysed pattern, and reports failures.
#include "flow/spd_solver.h"

#include <Eigen/SparseCore>
#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace elastica;

namespace {

// The graph Laplacian of an n×n grid (4-neighbour) plus `shift` on the diagonal: SPD for shift > 0,
// with eigenvalues in [shift, shift + 8], so the condition number is at most 1 + 8/shift.
Eigen::SparseMatrix<double> shiftedGridLaplacian(int n, double shift) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [n](int i, int j) { return j * n + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      double degree = 0;
      for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int a = i + di, b = j + dj;
        if (a < 0 || b < 0 || a >= n || b >= n) continue;
        t.emplace_back(id(i, j), id(a, b), -1.0);
        ++degree;
      }
      t.emplace_back(id(i, j), id(i, j), degree + shift);
    }
  }
  Eigen::SparseMatrix<double> A(n * n, n * n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

Eigen::VectorXd randomVector(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x[i] = u(rng);
  return x;
}

// The backends a test runs on: Eigen's always, CHOLMOD's when the build links it.
std::vector<SpdBackend> backends() {
  std::vector<SpdBackend> b{SpdBackend::SimplicialLDLT};
  if (SpdSolver::cholmodAvailable()) b.push_back(SpdBackend::Cholmod);
  return b;
}

}  // namespace

// A known solution x* of A x = b is recovered to 1e-12 (max norm; |x*| ≤ 1, condition number ≤ 9,
// so rounding gives ~1e-15).
TEST(SpdSolver, SolvesAKnownSystemToRounding) {
  const Eigen::SparseMatrix<double> A = shiftedGridLaplacian(30, 1.0);
  const Eigen::VectorXd expected = randomVector(static_cast<int>(A.rows()), 1);
  const Eigen::VectorXd b = A * expected;
  for (SpdBackend backend : backends()) {
    SpdSolver solver(backend);
    ASSERT_TRUE(solver.factorize(A)) << solver.backendName();
    Eigen::VectorXd x;
    solver.solve(b, x);
    ASSERT_EQ(x.size(), expected.size());
    EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-12) << solver.backendName();
  }
}

// The pattern is analysed once; new values on it are factorised and solved without a new
// analysis (the semi-implicit scheme's use: one analysis per connectivity, a factorisation per step).
TEST(SpdSolver, RefactorisesNewValuesOnTheAnalysedPattern) {
  const Eigen::SparseMatrix<double> A1 = shiftedGridLaplacian(20, 0.5), A2 = shiftedGridLaplacian(20, 3.0);
  const Eigen::VectorXd x1 = randomVector(static_cast<int>(A1.rows()), 2), x2 = randomVector(static_cast<int>(A1.rows()), 3);
  for (SpdBackend backend : backends()) {
    SpdSolver solver(backend);
    solver.analyzePattern(A1);
    Eigen::VectorXd x;
    ASSERT_TRUE(solver.factorize(A1));
    solver.solve(A1 * x1, x);
    EXPECT_LT((x - x1).lpNorm<Eigen::Infinity>(), 1e-12) << solver.backendName();
    ASSERT_TRUE(solver.factorize(A2));
    solver.solve(A2 * x2, x);
    EXPECT_LT((x - x2).lpNorm<Eigen::Infinity>(), 1e-12) << solver.backendName();
  }
}

// Auto picks SimplicialLDLT below kCholmodMinRows rows and CHOLMOD from there (when built with it);
// each solves to 1e-12.
TEST(SpdSolver, AutoChoosesTheBackendBySize) {
  for (int n : {10, 50}) {  // 100 and 2,500 rows, either side of kCholmodMinRows = 2,000
    const Eigen::SparseMatrix<double> A = shiftedGridLaplacian(n, 1.0);
    const Eigen::VectorXd expected = randomVector(n * n, 4);
    SpdSolver solver;
    ASSERT_TRUE(solver.factorize(A));
    const bool large = A.rows() >= SpdSolver::kCholmodMinRows;
    EXPECT_STREQ(solver.backendName(), large && SpdSolver::cholmodAvailable() ? "CHOLMOD simplicial" : "SimplicialLDLT");
    Eigen::VectorXd x;
    solver.solve(A * expected, x);
    EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-12) << solver.backendName();
  }
}

// A singular matrix (the graph Laplacian without a shift: constants are in its kernel, so the last
// pivot is zero) is reported, not solved.
TEST(SpdSolver, ReportsASingularMatrix) {
  Eigen::SparseMatrix<double> A(2, 2);
  A.insert(0, 0) = 1;
  A.insert(0, 1) = -1;
  A.insert(1, 0) = -1;
  A.insert(1, 1) = 1;
  for (SpdBackend backend : backends()) {
    SpdSolver solver(backend);
    EXPECT_FALSE(solver.factorize(A)) << solver.backendName();
  }
}

// Conjugate gradients preconditioned with another matrix's factorisation (the semi-implicit
// step's reuse of an earlier step's): a known solution of B x = b, B = the grid Laplacian with
// shift 0.5 (condition number 17), from the factorisation of shift 1. The preconditioned matrix's
// eigenvalues lie in [(s+0.5)/(s+1), 1] ⊂ [0.5, 1]: CG reduces the error by (√2−1)/(√2+1) ≈ 0.17
// or better per iteration, so 1e-10 takes at most 13 iterations; a direct solve of B agrees.
TEST(SpdSolver, PreconditionedSolveWithAnotherMatrixFactorisation) {
  const Eigen::SparseMatrix<double> A = shiftedGridLaplacian(30, 1.0), B = shiftedGridLaplacian(30, 0.5);
  const Eigen::VectorXd expected = randomVector(static_cast<int>(A.rows()), 3);
  const Eigen::VectorXd b = B * expected;
  for (SpdBackend backend : backends()) {
    SpdSolver spd(backend);
    EXPECT_FALSE(spd.factored());
    Eigen::VectorXd x;
    EXPECT_EQ(spd.solvePreconditioned(B, b, x, 1e-10, 50), -1) << "no factorisation yet";
    ASSERT_TRUE(spd.factorize(A));
    EXPECT_TRUE(spd.factored());
    const int iterations = spd.solvePreconditioned(B, b, x, 1e-10, 50);
    EXPECT_GE(iterations, 1);
    EXPECT_LE(iterations, 13) << spd.backendName();
    EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-8) << spd.backendName();
    // Too few iterations: reported as not converged.
    EXPECT_EQ(spd.solvePreconditioned(B, b, x, 1e-10, 1), -1);
    // Its own factorisation preconditions it exactly: one iteration.
    ASSERT_TRUE(spd.factorize(B));
    EXPECT_EQ(spd.solvePreconditioned(B, b, x, 1e-10, 50), 1);
    EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-10);
  }
}

// Several right-hand sides at once (the vector scheme's x, y and z): each column converges as it
// would alone, to the same solution, and one column that needs nothing (b = 0) stays 0.
TEST(SpdSolver, PreconditionedSolveOfSeveralColumnsAtOnce) {
  const Eigen::SparseMatrix<double> A = shiftedGridLaplacian(30, 1.0), B = shiftedGridLaplacian(30, 0.5);
  const int n = static_cast<int>(A.rows());
  Eigen::MatrixXd expected(n, 3);
  expected.col(0) = randomVector(n, 4);
  expected.col(1) = randomVector(n, 5);
  expected.col(2).setZero();
  const Eigen::MatrixXd rhs = B * expected;
  for (SpdBackend backend : backends()) {
    SpdSolver spd(backend);
    Eigen::MatrixXd x;
    EXPECT_EQ(spd.solvePreconditioned(B, rhs, x, 1e-10, 50), -1) << "no factorisation yet";
    ASSERT_TRUE(spd.factorize(A));
    const int iterations = spd.solvePreconditioned(B, rhs, x, 1e-10, 50);
    EXPECT_GE(iterations, 1);
    EXPECT_LE(iterations, 13) << spd.backendName();  // as one column alone (the test above)
    EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-8) << spd.backendName();
    EXPECT_EQ(x.col(2).lpNorm<Eigen::Infinity>(), 0);
    EXPECT_EQ(spd.solvePreconditioned(B, rhs, x, 1e-10, 1), -1) << "too few iterations";
    // The direct multi-column solve with B's own factorisation.
    ASSERT_TRUE(spd.factorize(B));
    spd.solve(rhs, x);
    EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-12) << spd.backendName();
  }
}

// A matrix barely off its diagonal (a fairing amount's M + τ/2 C M⁻¹ C at a small τ) has Cholesky
// fill that decays into subnormal numbers, which the solver flushes to zero for speed: the
// solution is still exact to rounding (|x*| ≤ 1, the matrix is within 1e-6 of the identity).
TEST(SpdSolver, SolvesANearlyDiagonalSystemToRounding) {
  Eigen::SparseMatrix<double> A = shiftedGridLaplacian(60, 1e6);
  A /= 1e6;
  const Eigen::VectorXd expected = randomVector(static_cast<int>(A.rows()), 6);
  const Eigen::VectorXd b = A * expected;
  for (SpdBackend backend : backends()) {
    SpdSolver spd(backend);
    ASSERT_TRUE(spd.factorize(A));
    Eigen::VectorXd x;
    spd.solve(b, x);
    EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-14) << spd.backendName();
  }
}
