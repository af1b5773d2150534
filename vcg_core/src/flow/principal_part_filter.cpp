// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/amount_operators.h"
#include "flow/incomplete_cholesky_cg.h"
#include "flow/principal_part_filter.h"
#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"

#include <elastica/laplacian.h>

#include <Eigen/Core>

#include <cmath>

namespace elastica {
namespace {

// From this many rows on, the steps are solved by conjugate gradients preconditioned with an
// incomplete Cholesky factorisation (flow/incomplete_cholesky_cg.h) until a solve misses the
// tolerance within kIncompleteIterations (slivers), and by the matrix's Cholesky factorisation
// from then on. Below, the factorisation costs little, and small meshes keep its bits. The
// tolerance is the residual's, relative to the right-hand side's: rounding's order for a matrix
// within a few units of its diagonal. Measurements: docs/decisions.md, "The amount's solver".
constexpr int kIncompleteFromRows = 20000;
constexpr int kIncompleteIterations = 40;
constexpr double kIncompleteTolerance = 1e-12;

}  // namespace

struct PrincipalPartFilter::Solver {
  Eigen::SparseMatrix<double> matrix;  // the step's, both triangles (the products read all of it)
  int rows = 0;
  std::unique_ptr<IncompleteCholeskyCg> incomplete = std::make_unique<IncompleteCholeskyCg>();
  SpdSolver spd;
  bool direct = true;  // solve with spd's factorisation (else with `incomplete`)

  // Factorises the matrix for direct solves from now on; false if it is not positive definite.
  // The factorisation reads the lower triangle only: it gets that alone, and the incomplete
  // factor and the whole matrix, of no use from here on, go first (CHOLMOD's transposed copy is
  // of what it gets): the same factor with less beside it at the run's peak.
  bool factorize() {
    direct = true;
    incomplete.reset();
    Eigen::SparseMatrix<double> lower = matrix.triangularView<Eigen::Lower>();
    lower.data().squeeze();  // its exact size (the assignment reserves by doubling)
    Eigen::SparseMatrix<double>().swap(matrix);
    spd.analyzePattern(lower);
    return spd.factorize(lower);
  }
  // The step's displacements for the columns of b; false if they are not finite.
  bool solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& displacement) {
    if (!direct) {
      // A column that misses the tolerance ends the iterations there (the first, if any does).
      if (incomplete->solve(b, displacement, kIncompleteTolerance, kIncompleteIterations) >= 0) return true;
      if (!factorize()) return false;
    }
    displacement.resize(b.rows(), b.cols());
    Eigen::VectorXd column, delta;
    for (Eigen::Index c = 0; c < b.cols(); ++c) {  // one column at a time, as before the iterations
      column = b.col(c);
      spd.solve(column, delta);
      if (!delta.allFinite()) return false;
      displacement.col(c) = delta;
    }
    return true;
  }
};

PrincipalPartFilter::PrincipalPartFilter() = default;
PrincipalPartFilter::~PrincipalPartFilter() = default;

bool PrincipalPartFilter::prepare(FlowState& state, double tau, AmountOperators operators) {
  const Topology& topo = state.topology();
  const Geometry& geo = state.geometryOnly();
  const VertexRoles& roles = state.roles();
  freeIndex_.assign(topo.vertexCount(), -1);
  int rows = 0;
  for (int v = 0; v < topo.vertexCount(); ++v)
    if (roles.free[v]) freeIndex_[v] = rows++;
  edgeWeight_ = geo.edgeWeight;
  vertexArea_ = geo.vertexArea;
  if (operators == AmountOperators::Graph) graphAmountOperators(topo, state.positions(), edgeWeight_, vertexArea_);
  tau_ = tau;
  solver_ = std::make_unique<Solver>();
  {
    SemiImplicitSystem system;  // its products' slots go once the matrix is assembled
    system.assembleMatrix(topo, edgeWeight_, vertexArea_, roles.active, freeIndex_, rows, 1.0, 0.5 * tau);
    solver_->matrix = system.takeMatrix();
  }
  solver_->rows = rows;
  if (rows >= kIncompleteFromRows && solver_->incomplete->compute(solver_->matrix)) {
    solver_->direct = false;
    return true;
  }
  return solver_->factorize();
}

bool PrincipalPartFilter::step(FlowState& state) {
  const Topology& topo = state.topology();
  std::vector<Vec3>& x = state.positions();
  const int nv = topo.vertexCount();
  // The right-hand side −τ/2 · C M⁻¹ C X = −τ/2 · M Δ_B² X on the free rows (Δ_B = −M⁻¹ C with the
  // input's weights; a free vertex's neighbours are all active, so Δ_B² there is the matrix's
  // C_fa M_aa⁻¹ C_a· product).
  cotanLaplacian(topo, edgeWeight_, vertexArea_, x, laplacian_);
  cotanLaplacian(topo, edgeWeight_, vertexArea_, laplacian_, bilaplacian_);
  const int rows = solver_->rows;
  Eigen::MatrixXd b(rows, 3);
  for (int v = 0; v < nv; ++v)
    if (freeIndex_[v] >= 0) b.row(freeIndex_[v]) = (-0.5 * tau_ * vertexArea_[v]) * bilaplacian_[v].transpose();
  Eigen::MatrixXd displacement;
  if (!solver_->solve(b, displacement)) return false;
  for (int v = 0; v < nv; ++v)
    if (freeIndex_[v] >= 0) x[v] += displacement.row(freeIndex_[v]).transpose();
  state.invalidate();
  return true;
}

}  // namespace elastica
