#include "flow/principal_part_filter.h"
#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"

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
  const std::vector<std::uint8_t>& active = state.roles().active;
  std::vector<Vec3>& x = state.positions();
  const int nv = topo.vertexCount();
  // M⁻¹ C X on the active vertices (free and ring 1: all a free vertex's neighbours), then
  // C of that on the free ones: the right-hand side's C_fa M_aa⁻¹ C_a· X, as the matrix's product.
  areaLaplacian_.assign(nv, Vec3::Zero());
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& ev = topo.edgeVertices(e);
    const Vec3 d = edgeWeight_[e] * (x[ev[0]] - x[ev[1]]);
    areaLaplacian_[ev[0]] += d;
    areaLaplacian_[ev[1]] -= d;
  }
  for (int v = 0; v < nv; ++v)
    areaLaplacian_[v] = active[v] && vertexArea_[v] > 0 ? Vec3(areaLaplacian_[v] / vertexArea_[v]) : Vec3::Zero();
  const int rows = static_cast<int>(solver_->system.matrix().rows());
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(rows, 3);
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& ev = topo.edgeVertices(e);
    const Vec3 d = (-0.5 * tau_ * edgeWeight_[e]) * (areaLaplacian_[ev[0]] - areaLaplacian_[ev[1]]);
    if (freeIndex_[ev[0]] >= 0) b.row(freeIndex_[ev[0]]) += d.transpose();
    if (freeIndex_[ev[1]] >= 0) b.row(freeIndex_[ev[1]]) -= d.transpose();
  }
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
