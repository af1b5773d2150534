// SPDX-License-Identifier: GPL-3.0-or-later
// Sparse symmetric positive definite solves: CHOLMOD's simplicial Cholesky (SuiteSparse) where the
// build has it and the system is large, Eigen's SimplicialLDLT otherwise. Neither calls BLAS, so
// the bits do not depend on the CPU's BLAS kernels. The fill-reducing
// ordering and the symbolic factorisation depend on the sparsity pattern only: analyse once per
// pattern, then factorise numerically for every new set of values.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace elastica {

/// Which factorisation an SpdSolver uses.
enum class SpdBackend {
  /// CHOLMOD simplicial above `kCholmodMinRows` rows when built with it, else SimplicialLDLT.
  Auto,
  /// Eigen's SimplicialLDLT (AMD ordering): no dependency, fastest on small systems.
  SimplicialLDLT,
  /// CHOLMOD's simplicial LLᵀ (its AMD/METIS ordering, no BLAS); falls back to SimplicialLDLT when the
  /// build has no CHOLMOD (see SpdSolver::cholmodAvailable()).
  Cholmod,
};

class SpdSolver {
 public:
  /// Below this many rows Auto uses SimplicialLDLT: CHOLMOD's set-up costs more than it saves
  /// (docs/decisions.md, "The factorisation").
  static constexpr int kCholmodMinRows = 2000;

  explicit SpdSolver(SpdBackend backend = SpdBackend::Auto);
  ~SpdSolver();
  SpdSolver(const SpdSolver&) = delete;
  SpdSolver& operator=(const SpdSolver&) = delete;

  /// True if this build links CHOLMOD.
  static bool cholmodAvailable();

  /// Orders and analyses the pattern of `A` (lower triangle used). Implied by the first
  /// factorize(); call again only when the pattern changes.
  void analyzePattern(const Eigen::SparseMatrix<double>& A);
  /// Numeric factorisation of `A`, whose pattern must be the analysed one. False if `A` is not
  /// numerically positive definite.
  bool factorize(const Eigen::SparseMatrix<double>& A);
  /// Solves A x = b with the last successful factorisation.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// Solves A x = b by conjugate gradients preconditioned with the last successful factorisation,
  /// which may be of another matrix of the same size (an earlier step's, or one of another
  /// sparsity pattern): a solve with it costs a twentieth of a factorisation, and a few of them
  /// replace one while A stays close to the factored matrix. `A` must be symmetric; its lower
  /// triangle is read. Stops once the preconditioned residual is below `tolerance` times its start
  /// (x starts at 0). Returns the iterations taken, or −1 if `maxIterations` did not reach the
  /// tolerance or A showed a direction of non-positive curvature (x is then not to be used).
  int solvePreconditioned(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                          double tolerance, int maxIterations) const;
  /// Solves A X = B for the columns of B with the last successful factorisation (one pass over the
  /// factor for all of them).
  void solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const;
  /// solvePreconditioned for every column of B at once (one multi-column solve per iteration; a
  /// column stops once it meets the tolerance). Returns the iterations the slowest column took, or
  /// −1 as above if any column did not converge.
  int solvePreconditioned(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                          double tolerance, int maxIterations) const;
  /// One step of a flow whose matrix changes a little from step to step: solves A X = B. From
  /// `reuseFromRows` rows on it first runs solvePreconditioned with the held factorisation (an
  /// earlier step's) unless the last such solve took more than kRefactorAfter iterations; if that
  /// does not converge within kMaxIterations, or below `reuseFromRows`, it factorises A (analysing
  /// its pattern first after patternChanged()) and solves directly. False if A is not numerically
  /// positive definite. The tolerance is loose for a linear solve and tight for a step: a flow's
  /// acceptance tests judge the step, and every CG iterate from 0 is a descent direction.
  bool solveStep(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                 int reuseFromRows);
  bool solveStep(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                 int reuseFromRows);
  /// The matrices solveStep gets from now on have another sparsity pattern (edge flips): the next
  /// factorisation analyses it first; the held factorisation still preconditions until then.
  void patternChanged() { patternChanged_ = true; }
  static constexpr double kPcgTolerance = 1e-4;  // of the preconditioned residual, relative to its start
  static constexpr int kRefactorAfter = 8, kMaxIterations = 20;

  /// Whether a factorisation is held (what solve() and solvePreconditioned() use).
  bool factored() const { return factored_; }

  /// The backend in use after analyzePattern ("CHOLMOD simplicial" or "SimplicialLDLT").
  const char* backendName() const;

 private:
  struct Impl;
  template <class Dense>
  void solveDense(const Dense& b, Dense& x) const;
  template <class Dense>
  int conjugateGradients(const Eigen::SparseMatrix<double>& A, const Dense& b, Dense& x, double tolerance,
                         int maxIterations) const;
  template <class Dense>
  bool step(const Eigen::SparseMatrix<double>& A, const Dense& b, Dense& x, int reuseFromRows);

  std::unique_ptr<Impl> impl_;
  bool factored_ = false;
  bool patternChanged_ = false, refactorNext_ = false;
};

}  // namespace elastica
