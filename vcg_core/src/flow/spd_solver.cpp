#include "flow/spd_solver.h"

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
#if defined(__SSE__)
#include <xmmintrin.h>
#endif


namespace elastica {
namespace {

// CHOLMOD (SuiteSparse 5, Debian 12) runs loops of its supernodal factorisation and solves with a
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

// A matrix close to its diagonal (M + τ/2 · C M⁻¹ C at a small τ: a fairing amount's filter)
// has Cholesky fill entries that decay geometrically with the distance in the mesh, down into
// subnormal numbers, on which the CPU's arithmetic is about a hundred times slower. Subnormal
// results are flushed to zero (and subnormal inputs read as zero) while this is alive; no value
// that matters to a solve is below 1e-308. The previous setting is put back after.
class FlushSubnormals {
 public:
#if defined(__SSE__)
  FlushSubnormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero); }
  ~FlushSubnormals() { _mm_setcsr(saved_); }

 private:
  static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
  unsigned saved_;
#endif
};

}  // namespace

struct SpdSolver::Impl {
  using Matrix = Eigen::SparseMatrix<double>;
  using Simplicial = Eigen::SimplicialLDLT<Matrix>;
#ifdef ELASTICA_HAVE_CHOLMOD
  using Supernodal = Eigen::CholmodSupernodalLLT<Matrix>;
#else
  using Supernodal = Simplicial;
#endif
  SpdBackend requested;
  std::unique_ptr<Simplicial> simplicial;
  std::unique_ptr<Supernodal> supernodal;

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
  impl_->supernodal.reset();
  if (impl_->useCholmod(static_cast<int>(A.rows()))) {
    [[maybe_unused]] OneThreadForCholmod oneThread;  // empty without OpenMP
    impl_->supernodal = std::make_unique<Impl::Supernodal>();
    impl_->supernodal->analyzePattern(A);
  } else {
    impl_->simplicial = std::make_unique<Impl::Simplicial>();
    impl_->simplicial->analyzePattern(A);
  }
}

bool SpdSolver::factorize(const Eigen::SparseMatrix<double>& A) {
  if (!impl_->simplicial && !impl_->supernodal) analyzePattern(A);
  [[maybe_unused]] FlushSubnormals flush;  // empty without SSE
  if (impl_->supernodal) {
    [[maybe_unused]] OneThreadForCholmod oneThread;  // empty without OpenMP
    impl_->supernodal->factorize(A);
    return factored_ = impl_->supernodal->info() == Eigen::Success;
  }
  impl_->simplicial->factorize(A);
  // LDLᵀ also factors an indefinite matrix: a pivot that is not positive says A is not SPD.
  return factored_ = impl_->simplicial->info() == Eigen::Success && (impl_->simplicial->vectorD().array() > 0).all();
}

void SpdSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  [[maybe_unused]] FlushSubnormals flush;  // empty without SSE
  if (impl_->supernodal) {
    [[maybe_unused]] OneThreadForCholmod oneThread;  // empty without OpenMP
    x = impl_->supernodal->solve(b);
    return;
  }
  x = impl_->simplicial->solve(b);
}

void SpdSolver::solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const {
  [[maybe_unused]] FlushSubnormals flush;  // empty without SSE
  if (impl_->supernodal) {
    [[maybe_unused]] OneThreadForCholmod oneThread;  // empty without OpenMP
    X = impl_->supernodal->solve(B);
    return;
  }
  X = impl_->simplicial->solve(B);
}

int SpdSolver::solvePreconditioned(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                                   double tolerance, int maxIterations) const {
  if (!factored_ || A.rows() != B.rows()) return -1;
  const Eigen::Index columns = B.cols();
  X.setZero(B.rows(), columns);
  Eigen::MatrixXd R = B, Z, P, AP;
  solve(R, Z);
  Eigen::VectorXd start(columns), rz(columns);
  std::vector<bool> done(columns, false);
  for (Eigen::Index c = 0; c < columns; ++c) {
    start[c] = rz[c] = R.col(c).dot(Z.col(c));
    if (!(start[c] > 0)) {
      if (start[c] != 0) return -1;
      done[c] = true;  // b = 0: x = 0 solves it
    }
  }
  P = Z;
  for (int k = 1; k <= maxIterations; ++k) {
    if (std::all_of(done.begin(), done.end(), [](bool d) { return d; })) return k - 1;
    AP.noalias() = A.selfadjointView<Eigen::Lower>() * P;
    for (Eigen::Index c = 0; c < columns; ++c) {
      if (done[c]) continue;
      const double curvature = P.col(c).dot(AP.col(c));
      if (!(curvature > 0)) return -1;
      const double alpha = rz[c] / curvature;
      X.col(c) += alpha * P.col(c);
      R.col(c) -= alpha * AP.col(c);
    }
    solve(R, Z);
    for (Eigen::Index c = 0; c < columns; ++c) {
      if (done[c]) continue;
      const double next = R.col(c).dot(Z.col(c));
      if (!std::isfinite(next)) return -1;
      if (next <= tolerance * tolerance * start[c]) {
        done[c] = true;
        P.col(c).setZero();  // A·0 = 0: the finished column costs the product nothing but zeros
        continue;
      }
      P.col(c) = Z.col(c) + (next / rz[c]) * P.col(c);
      rz[c] = next;
    }
  }
  return std::all_of(done.begin(), done.end(), [](bool d) { return d; }) ? maxIterations : -1;
}

int SpdSolver::solvePreconditioned(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                   double tolerance, int maxIterations) const {
  if (!factored_ || A.rows() != b.size()) return -1;
  x.setZero(b.size());
  Eigen::VectorXd r = b, z, p, Ap;
  solve(r, z);
  const double start = r.dot(z);
  if (!(start > 0)) return start == 0 ? 0 : -1;  // b = 0: x = 0 solves it
  p = z;
  double rz = start;
  for (int k = 1; k <= maxIterations; ++k) {
    Ap.noalias() = A.selfadjointView<Eigen::Lower>() * p;
    const double curvature = p.dot(Ap);
    if (!(curvature > 0)) return -1;
    const double alpha = rz / curvature;
    x += alpha * p;
    r -= alpha * Ap;
    solve(r, z);
    const double next = r.dot(z);
    if (!std::isfinite(next)) return -1;
    if (next <= tolerance * tolerance * start) return k;
    p = z + (next / rz) * p;
    rz = next;
  }
  return -1;
}

const char* SpdSolver::backendName() const {
  if (impl_->supernodal && cholmodAvailable()) return "CHOLMOD supernodal";
  return "SimplicialLDLT";
}

}  // namespace elastica
