#include <elastica/laplacian.h>
#include "flow/flow_speed.h"
#include "flow/semi_implicit_integrator.h"
#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"
#include "mesh/self_intersection.h"
#include "support/parallel.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>

namespace elastica {
namespace {

// Acceptance: a vertex may move at most FlowOptions::maxJump of its mean edge lengths, and the
// energy may not rise by more than this (relative): stricter stalls at the noise floor.
constexpr double kEnergySlack = 1e-4;

}  // namespace

struct SemiImplicitIntegrator::SparseSolver {
  SemiImplicitSystem system;
  SpdSolver spd;
  Eigen::VectorXd delta;
  bool analysed = false;
};

// Rows of the system (the free vertices, in vertex order) and a fresh solver whenever the state's
// connectivity changed: the sparsity pattern follows it.
void SemiImplicitIntegrator::buildRows(const FlowState& state) {
  if (connectivityVersion_ == state.connectivityVersion()) return;
  const Topology& topo = state.topology();
  freeIndex_.assign(topo.vertexCount(), -1);
  int row = 0;
  for (int v = 0; v < topo.vertexCount(); ++v)
    if (state.roles().free[v]) freeIndex_[v] = row++;
  solver_.reset();
  connectivityVersion_ = state.connectivityVersion();
}

void SemiImplicitIntegrator::speed(FlowState& state) {
  const Topology& topo = state.topology();
  const Curvature& curv = state.curvature();
  const std::vector<std::uint8_t>& free = state.roles().free;
  cotanLaplacian(topo, state.geometry(), curv.Hflow, lh_);
  const bool elastica = state.options().flow == FlowType::Elastica;
  const int nv = topo.vertexCount();
  speed_.assign(nv, 0.0);
  parallelFor(nv, [&](int i) {
    if (free[i]) speed_[i] = normalSpeed(elastica, lh_[i], curv.Hflow[i], curv.g[i]);
  });
}

bool SemiImplicitIntegrator::tryStep(FlowState& state, double tau) {
  std::vector<Vec3>& positions = state.positions();
  auto reject = [&] {
    positions = saved_;
    state.invalidate();
    return false;
  };
  state.evaluate();
  buildRows(state);
  speed(state);
  const Topology& topo = state.topology();
  const Geometry& geo = state.geometry();
  const int nv = topo.vertexCount(), n = state.roles().freeCount;
  if (!solver_) solver_ = std::make_shared<SparseSolver>();

  // (M_ff + τ/2 · C_fa M_aa⁻¹ C_af) δ_f = τ M_ff F_f: to leading order F(P + δN) ≈ F − ½Δ_B²δ,
  // so the stiff fourth-order part is taken at the new time and everything else is lagged.
  SemiImplicitSystem& system = solver_->system;
  system.assemble(topo, geo, state.roles().active, freeIndex_, n, speed_, tau);
  if (!solver_->analysed) {
    solver_->spd.analyzePattern(system.matrix());  // the pattern depends on the topology only
    solver_->analysed = true;
  }
  saved_ = positions;
  if (!solver_->spd.factorize(system.matrix())) return reject();
  Eigen::VectorXd& delta = solver_->delta;
  solver_->spd.solve(system.rhs(), delta);

  const double energyBefore = state.energy();
  const double energyLimit = energyBefore * (1 + kEnergySlack) + 1e-12;
  faceNormalBefore_ = geo.faceNormal;
  // The largest jump, as a multiple of what FlowOptions::maxJump allows at its vertex.
  double overshoot = 0;
  for (int v = 0; v < nv; ++v) {
    const int r = freeIndex_[v];
    if (r < 0) continue;
    if (!std::isfinite(delta[r])) return reject();
    double ring = 0;
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k)
      ring += (saved_[topo.ringVertex(k)] - saved_[v]).norm();
    const double allowed = state.options().maxJump * ring / std::max(1, topo.valence(v));
    if (delta[r] != 0) overshoot = std::max(overshoot, std::abs(delta[r]) / allowed);
  }
  if (!std::isfinite(overshoot)) return reject();  // a vertex whose edges have no length moves
  lastStepShortened_ = overshoot > 1;
  if (lastStepShortened_ && !state.options().shortenJumps) return reject();
  const double scale = lastStepShortened_ ? 1 / overshoot : 1.0;
  double largest = 0;
  for (int v = 0; v < nv; ++v) {
    const int r = freeIndex_[v];
    if (r < 0) continue;
    positions[v] += scale * delta[r] * geo.vertexNormal[v];
    largest = std::max(largest, scale * std::abs(delta[r]));
  }
  state.invalidate();
  if (!acceptable(state, energyLimit)) return reject();
  lastNormalStep_ = largest;
  lastEnergyDecrease_ = energyBefore - state.energy();

  // The drift is held to the step's rules: a pass that folds a face or lifts the energy above
  // what the step allowed (the energy before the step) is undone, and the passes stop. Unchecked,
  // a pass on the subdivided tubular cage left no face folded but one so thin that E jumped from
  // 409 to 230,470. What the drift lowers E by is not the flow's progress: near the fixed point a
  // pass that lowers the *discrete* energy is kept and one that raises it is not, so E creeps
  // down by vertex redistribution after the shape has settled (96×32 torus: 1.1 % over 376
  // steps, R/r moving away from √2). The stopping rules therefore read lastEnergyDecrease(), the
  // normal step's own decrease.
  const FlowOptions& opt = state.options();
  for (int pass = 0; pass < opt.driftPasses && opt.tangentialDrift; ++pass)
    if (!driftPass(state, energyLimit)) break;
  // The embedding guard, once for the step and its drift (a full test costs about what a step's
  // other checks cost together): faces that cross undo the whole step.
  if (guardEmbedding_ && selfIntersects(state.mesh(), &state.roles().activeFace)) {
    ++crossingRejections_;
    return reject();
  }
  // The last evaluation (of the accepted state) stays valid unless the boundary slides.
  state.slideBoundary();
  return true;
}

bool SemiImplicitIntegrator::acceptable(FlowState& state, double energyLimit) {
  const Geometry& geo = state.geometryOnly();
  const std::vector<std::uint8_t>& activeFace = state.roles().activeFace;
  for (int f = 0; f < state.topology().faceCount(); ++f)
    if (activeFace[f] && geo.faceNormal[f].dot(faceNormalBefore_[f]) < 0) return false;
  const double e = state.energy();
  if (!std::isfinite(e)) return false;
  // The Laplacian-of-H flow is not a descent of E: it is judged by not creating folds only.
  return state.options().flow != FlowType::Elastica || e <= energyLimit;
}

bool SemiImplicitIntegrator::driftPass(FlowState& state, double energyLimit) {
  const Geometry& geo = state.geometryOnly();  // the drift itself needs no curvature
  const double eps = state.options().driftFactor * state.activeMinFaceArea();
  std::vector<Vec3>& positions = state.positions();
  const std::vector<std::uint8_t>& free = state.roles().free;
  tangentialDrift(state.topology(), geo, positions, free, driftScratch_, drift_);
  driftSaved_ = positions;
  faceNormalBefore_ = geo.faceNormal;
  const int nv = state.topology().vertexCount();
  parallelFor(nv, [&](int i) {
    if (free[i]) positions[i] += eps * drift_[i];
  });
  state.invalidate();
  if (acceptable(state, energyLimit)) return true;
  positions = driftSaved_;
  state.invalidate();
  return false;
}

}  // namespace elastica
