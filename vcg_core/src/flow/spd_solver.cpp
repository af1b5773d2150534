// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/spd_solver.h"
#include "flow/conjugate_gradients.h"
#include "flow/flush_subnormals.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <vector>
#ifdef ELASTICA_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif
#ifdef _OPENMP
#include <omp.h>
#endif


namespace elastica {
namespace {

// CHOLMOD (SuiteSparse 5, Debian 12) runs loops of its factorisations and solves with a
// fixed team of four OpenMP threads whatever OMP_NUM_THREADS says: on a 2-core machine the threads
// wait on each other (futex calls and spinning were a third of a 794-edge hole's fill, and its 42
// factorisations of a 25,000-row system took 6.4 s; with the team switched off, 2.7 s). While one
// of these is alive, every parallel region is inactive (one thread); the setting is put back after.
class OneThreadForCholmod {
 public:
#ifdef _OPENMP
  OneThreadForCholmod() : levels_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }
  ~OneThreadForCholmod() { omp_set_max_active_levels(levels_); }

 private:
  int levels_;
#endif
};

}  // namespace

struct SpdSolver::Impl {
  using Matrix = Eigen::SparseMatrix<double>;
  using Simplicial = Eigen::SimplicialLDLT<Matrix>;
#ifdef ELASTICA_HAVE_CHOLMOD
  // Simplicial, not supernodal: the supernodal factorisation does its dense work in the system's
  // BLAS, whose kernels are chosen per CPU at run time (OpenBLAS: Haswell, SkylakeX, Cooperlake,
  // Zen, ...) and round differently, so the same input gave another mesh on another machine (the
  // cow: 136, 89 and 96 attempts under OpenBLAS's Cooperlake, Haswell and Prescott kernels). The
  // simplicial factorisation is plain C in CHOLMOD itself, with CHOLMOD's ordering.
  using Cholmod = Eigen::CholmodSimplicialLLT<Matrix>;
#else
  using Cholmod = Simplicial;
#endif
  SpdBackend requested;
  std::unique_ptr<Simplicial> simplicial;
  std::unique_ptr<Cholmod> cholmod;

  bool useCholmod(int rows) const {
    if (!cholmodAvailable()) return false;
    return requested == SpdBackend::Cholmod || (requested == SpdBackend::Auto && rows >= kCholmodMinRows);
  }
};

SpdSolver::SpdSolver(SpdBackend backend) : impl_(std::make_unique<Impl>()) { impl_->requested = backend; }
SpdSolver::~SpdSolver() = default;

bool SpdSolver::cholmodAvailable() {
#ifdef ELASTICA_HAVE_CHOLMOD
  return true;
#else
  return false;
#endif
}

void SpdSolver::analyzePattern(const Eigen::SparseMatrix<double>& A) {
  factored_ = false;
  impl_->simplicial.reset();
  impl_->cholmod.reset();
  if (impl_->useCholmod(static_cast<int>(A.rows()))) {
    [[maybe_unused]] OneThreadForCholmod oneThread;  // empty without OpenMP
    impl_->cholmod = std::make_unique<Impl::Cholmod>();
    impl_->cholmod->analyzePattern(A);
  } else {
    impl_->simplicial = std::make_unique<Impl::Simplicial>();
    impl_->simplicial->analyzePattern(A);
  }
}

bool SpdSolver::factorize(const Eigen::SparseMatrix<double>& A) {
  if (!impl_->simplicial && !impl_->cholmod) analyzePattern(A);
  [[maybe_unused]] FlushSubnormals flush;  // empty without SSE
  if (impl_->cholmod) {
    [[maybe_unused]] OneThreadForCholmod oneThread;  // empty without OpenMP
    impl_->cholmod->factorize(A);
    return factored_ = impl_->cholmod->info() == Eigen::Success;
  }
  impl_->simplicial->factorize(A);
  // LDLᵀ also factors an indefinite matrix: a pivot that is not positive says A is not SPD.
  return factored_ = impl_->simplicial->info() == Eigen::Success && (impl_->simplicial->vectorD().array() > 0).all();
}

template <class Dense>
void SpdSolver::solveDense(const Dense& b, Dense& x) const {
  [[maybe_unused]] FlushSubnormals flush;  // empty without SSE
  if (impl_->cholmod) {
    [[maybe_unused]] OneThreadForCholmod oneThread;  // empty without OpenMP
    x = impl_->cholmod->solve(b);
    return;
  }
  x = impl_->simplicial->solve(b);
}

void SpdSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const { solveDense(b, x); }
void SpdSolver::solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const { solveDense(B, X); }

// Conjugate gradients preconditioned with the held factorisation, stopping on the preconditioned
// residual r·z relative to its start (a column with b = 0 is solved by x = 0).
template <class Dense>
int SpdSolver::conjugateGradients(const Eigen::SparseMatrix<double>& A, const Dense& b, Dense& x, double tolerance,
                                  int maxIterations) const {
  if (!factored_ || A.rows() != b.rows()) return -1;
  Eigen::VectorXd start(b.cols());
  auto rule = [&](Eigen::Index c, int k, const auto&, double rz) {
    if (k == 0) {
      start[c] = rz;
      if (!(rz > 0)) return rz == 0 ? CgVerdict::Converged : CgVerdict::GiveUp;
      return CgVerdict::Continue;
    }
    return rz <= tolerance * tolerance * start[c] ? CgVerdict::Converged : CgVerdict::Continue;
  };
  return elastica::conjugateGradients(
      b, x, [&](const Dense& p, Dense& Ap) { Ap.noalias() = A.selfadjointView<Eigen::Lower>() * p; },
      [&](const Dense& r, Dense& z) { solveDense(r, z); }, rule, maxIterations);
}

int SpdSolver::solvePreconditioned(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                   double tolerance, int maxIterations) const {
  return conjugateGradients(A, b, x, tolerance, maxIterations);
}

int SpdSolver::solvePreconditioned(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                                   double tolerance, int maxIterations) const {
  return conjugateGradients(A, B, X, tolerance, maxIterations);
}

template <class Dense>
bool SpdSolver::step(const Eigen::SparseMatrix<double>& A, const Dense& b, Dense& x, int reuseFromRows) {
  if (!refactorNext_ && A.rows() >= reuseFromRows && factored_) {
    const int iterations = conjugateGradients(A, b, x, kPcgTolerance, kMaxIterations);
    if (iterations >= 0) {
      refactorNext_ = iterations > kRefactorAfter;
      return true;
    }
  }
  if (patternChanged_) analyzePattern(A);
  patternChanged_ = false;
  if (!factorize(A)) return false;
  solveDense(b, x);
  refactorNext_ = false;
  return true;
}

bool SpdSolver::solveStep(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                          int reuseFromRows) {
  return step(A, b, x, reuseFromRows);
}

bool SpdSolver::solveStep(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                          int reuseFromRows) {
  return step(A, B, X, reuseFromRows);
}

const char* SpdSolver::backendName() const {
  if (impl_->cholmod && cholmodAvailable()) return "CHOLMOD simplicial";
  return "SimplicialLDLT";
}

}  // namespace elastica
