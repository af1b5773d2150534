// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/complex_symmetric_ldlt.h"
#include "flow/amount_operators.h"
#include "flow/incomplete_cholesky_cg.h"
#include "flow/principal_part_filter.h"
#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"

#include <elastica/laplacian.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace elastica {
namespace {

// Where the one-ring form does not apply (fixed or sliding vertices beside the free ones), from
// this many rows on, the steps are solved by conjugate gradients preconditioned with an
// incomplete Cholesky factorisation (flow/incomplete_cholesky_cg.h) until a solve misses the
// tolerance within kIncompleteIterations (slivers), and by a direct factorisation from then on.
// Below, the factorisation costs little, and small meshes keep its bits. The tolerance is the
// residual's, relative to the right-hand side's: rounding's order for a matrix within a few units
// of its diagonal. Measurements: docs/decisions.md, "The amount's solver".
constexpr int kIncompleteFromRows = 20000;
constexpr int kIncompleteIterations = 40;
constexpr double kIncompleteTolerance = 1e-12;

// Whether every active vertex is free (f = a: a whole closed mesh, or every vertex of an open one
// free) and has area: then A = M + s² C M⁻¹ C exactly, and its one-ring form applies.
bool oneRingApplies(const std::vector<std::uint8_t>& active, const std::vector<int>& freeIndex,
                    const std::vector<double>& vertexArea) {
  for (std::size_t v = 0; v < active.size(); ++v)
    if (active[v] && (freeIndex[v] < 0 || !(vertexArea[v] > 0) || !std::isfinite(vertexArea[v]))) return false;
  return true;
}

// B = M + i s C on the free rows (both triangles), C_ij from `edgeWeight`, C_ii = −Σ_j C_ij.
ComplexSymmetricLdlt::Matrix assembleOneRingForm(const Topology& topo, const std::vector<double>& edgeWeight,
                                                 const std::vector<double>& vertexArea,
                                                 const std::vector<int>& freeIndex, int rows, double s) {
  using Complex = ComplexSymmetricLdlt::Complex;
  ComplexSymmetricLdlt::Matrix B(rows, rows);
  std::vector<int> vertexOfRow(rows);
  std::int64_t entries = 0;
  for (int v = 0; v < topo.vertexCount(); ++v)
    if (freeIndex[v] >= 0) vertexOfRow[freeIndex[v]] = v, entries += 1 + topo.ringEnd(v) - topo.ringBegin(v);
  B.resizeNonZeros(static_cast<Eigen::Index>(entries));
  std::vector<std::pair<int, double>> column;
  int next = 0;
  for (int r = 0; r < rows; ++r) {
    const int v = vertexOfRow[r];
    B.outerIndexPtr()[r] = next;
    column.clear();
    double diagonal = 0;
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) {
      const double w = edgeWeight[topo.ringEdge(k)];
      diagonal -= w;
      column.emplace_back(freeIndex[topo.ringVertex(k)], w);  // every neighbour is free (f = a)
    }
    column.emplace_back(r, diagonal);
    std::sort(column.begin(), column.end());
    for (const auto& [row, c] : column) {
      B.innerIndexPtr()[next] = row;
      B.valuePtr()[next++] = Complex(row == r ? vertexArea[v] : 0.0, s * c);
    }
  }
  B.outerIndexPtr()[rows] = next;
  return B;
}

}  // namespace

struct PrincipalPartFilter::Solver {
  Eigen::SparseMatrix<double> matrix;  // the two-ring, both triangles (the products read all of it)
  ComplexSymmetricLdlt::Matrix oneRing;  // M + i s C where it applies, until factorised
  int rows = 0;
  std::unique_ptr<IncompleteCholeskyCg> incomplete = std::make_unique<IncompleteCholeskyCg>();
  SpdSolver spd;
  ComplexSymmetricLdlt complexForm;
  bool direct = true;  // solve with a factorisation (else with `incomplete`)

  // Factorises for direct solves from now on; false on a failed factorisation. With the one-ring
  // form: its complex factor, of a quarter of the two-ring's fill or less (docs/decisions.md).
  // Otherwise the two-ring Cholesky, which reads the lower triangle only: it gets that alone, and
  // the incomplete factor and the whole matrix, of no use from here on, go first (CHOLMOD's
  // transposed copy is of what it gets): the same factor with less beside it at the run's peak.
  bool factorize() {
    direct = true;
    incomplete.reset();
    if (oneRing.rows() > 0) {
      Eigen::SparseMatrix<double>().swap(matrix);
      complexForm.analyzePattern(oneRing);
      {  // only half of it beside the factor: the same bits
        ComplexSymmetricLdlt::Matrix part = complexForm.factorizedPart(oneRing);
        oneRing.swap(part);
      }
      const bool ok = complexForm.factorize(oneRing);
      ComplexSymmetricLdlt::Matrix().swap(oneRing);
      return ok;
    }
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
    if (complexForm.factored()) {  // A⁻¹ b = Re[(M + i s C)⁻¹ b] for real b (DESIGN.md §5)
      complexForm.solveRealPart(b, displacement);
      return displacement.allFinite();
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
  // The factor is the run's peak (at 711,420 vertices 535 MB): the state's geometry and curvature,
  // of no use to the steps, are not kept beside it (FlowState::releaseCaches; `geo` goes with them).
  state.releaseCaches();
  if (operators == AmountOperators::Graph) graphAmountOperators(topo, state.positions(), edgeWeight_, vertexArea_);
  tau_ = tau;
  solver_ = std::make_unique<Solver>();
  solver_->rows = rows;
  const bool oneRing = oneRingApplies(roles.active, freeIndex_, vertexArea_);
  if (oneRing) solver_->oneRing = assembleOneRingForm(topo, edgeWeight_, vertexArea_, freeIndex_, rows, std::sqrt(0.5 * tau));
  // Where the one-ring form applies it is factorised at once: at the default amount the
  // incomplete factor's iterations gave up on both scale benchmarks (a noisy sphere and a scan),
  // after costing up to a third of the run (docs/decisions.md, "The amount's solver"). The
  // two-ring matrix is assembled only where it is used.
  const bool incomplete = rows >= kIncompleteFromRows && !oneRing;
  if (!oneRing) {
    SemiImplicitSystem system;  // its products' slots go once the matrix is assembled
    system.assembleMatrix(topo, edgeWeight_, vertexArea_, roles.active, freeIndex_, rows, 1.0, 0.5 * tau);
    solver_->matrix = system.takeMatrix();
  }
  if (incomplete && solver_->incomplete->compute(solver_->matrix)) {
    solver_->direct = false;
    return true;
  }
  return solver_->factorize();
}
bool PrincipalPartFilter::step(FlowState& state) {
  state.releaseCaches();  // the last energy's geometry is not kept beside the factor (prepare's note)
  if (!stepField(state.topology(), state.positions())) return false;
  state.invalidate();
  return true;
}

bool PrincipalPartFilter::addBackFilteredRemoval(FlowState& state, std::vector<Vec3> start, int steps) {
  std::vector<Vec3>& x = state.positions();
  std::vector<Vec3>& removed = start;  // start − x in place, on the free vertices; zero elsewhere
  for (std::size_t v = 0; v < x.size(); ++v) removed[v] = freeIndex_[v] >= 0 ? Vec3(removed[v] - x[v]) : Vec3::Zero();
  state.releaseCaches();
  for (int k = 0; k < steps; ++k)
    if (!stepField(state.topology(), removed)) return false;
  for (std::size_t v = 0; v < x.size(); ++v) x[v] += removed[v];
  state.invalidate();
  return true;
}

bool PrincipalPartFilter::stepField(const Topology& topo, std::vector<Vec3>& x) {
  const int nv = topo.vertexCount();
  // The right-hand side −τ/2 · C M⁻¹ C X = −τ/2 · M Δ_B² X on the free rows (Δ_B = −M⁻¹ C with the
  // input's weights; a free vertex's neighbours are all active, so Δ_B² there is the matrix's
  // C_fa M_aa⁻¹ C_a· product).
  const int rows = solver_->rows;
  Eigen::MatrixXd b(rows, 3);
  {  // the two Laplacians go before the solve's own storage comes (the run's peak is beside the factor)
    std::vector<Vec3> laplacian, bilaplacian;
    cotanLaplacian(topo, edgeWeight_, vertexArea_, x, laplacian);
    cotanLaplacian(topo, edgeWeight_, vertexArea_, laplacian, bilaplacian);
    for (int v = 0; v < nv; ++v)
      if (freeIndex_[v] >= 0) b.row(freeIndex_[v]) = (-0.5 * tau_ * vertexArea_[v]) * bilaplacian[v].transpose();
  }
  Eigen::MatrixXd displacement;
  if (!solver_->solve(b, displacement)) return false;
  for (int v = 0; v < nv; ++v)
    if (freeIndex_[v] >= 0) x[v] += displacement.row(freeIndex_[v]).transpose();
  return true;
}

}  // namespace elastica
