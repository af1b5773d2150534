#include "flow/principal_part_filter.h"
#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"

#include <elastica/laplacian.h>

#include <Eigen/Core>

#include <cmath>

namespace elastica {

struct PrincipalPartFilter::Solver {
  SemiImplicitSystem system;
  SpdSolver spd;
};

PrincipalPartFilter::PrincipalPartFilter() = default;
PrincipalPartFilter::~PrincipalPartFilter() = default;

bool PrincipalPartFilter::prepare(FlowState& state, double tau) {
  const Topology& topo = state.topology();
  const Geometry& geo = state.geometryOnly();
  const VertexRoles& roles = state.roles();
  freeIndex_.assign(topo.vertexCount(), -1);
  int rows = 0;
  for (int v = 0; v < topo.vertexCount(); ++v)
    if (roles.free[v]) freeIndex_[v] = rows++;
  edgeWeight_ = geo.edgeWeight;
  vertexArea_ = geo.vertexArea;
  tau_ = tau;
  solver_ = std::make_unique<Solver>();
  solver_->system.assembleMatrix(topo, edgeWeight_, vertexArea_, roles.active, freeIndex_, rows, 1.0, 0.5 * tau);
  solver_->spd.analyzePattern(solver_->system.matrix());
  return solver_->spd.factorize(solver_->system.matrix());
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
  const int rows = static_cast<int>(solver_->system.matrix().rows());
  Eigen::MatrixXd b(rows, 3);
  for (int v = 0; v < nv; ++v)
    if (freeIndex_[v] >= 0) b.row(freeIndex_[v]) = (-0.5 * tau_ * vertexArea_[v]) * bilaplacian_[v].transpose();
  Eigen::VectorXd column(rows), delta(rows);
  Eigen::MatrixXd displacement(rows, 3);
  for (int c = 0; c < 3; ++c) {
    column = b.col(c);
    solver_->spd.solve(column, delta);
    if (!delta.allFinite()) return false;
    displacement.col(c) = delta;
  }
  for (int v = 0; v < nv; ++v)
    if (freeIndex_[v] >= 0) x[v] += displacement.row(freeIndex_[v]).transpose();
  state.invalidate();
  return true;
}

}  // namespace elastica
