// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/energy.h>
#include <elastica/laplacian.h>
#include "flow/flow_speed.h"
#include "flow/semi_implicit_integrator.h"
#include "flow/step_holds.h"
#include "support/parallel.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <functional>

namespace elastica {
namespace {

// Acceptance: a vertex may move at most InternalFlowOptions::maxJump of its mean edge lengths, and
// the energy may not rise by more than this (relative): stricter stalls at the noise floor.
constexpr double kEnergySlack = 1e-4;

// Large systems are solved by conjugate gradients preconditioned with an earlier step's
// factorisation while that takes few iterations (SpdSolver::solveStep): a step's matrix differs
// from the last one by its τ (×1.5) and the geometry's small change, and after edge flips by a few
// entries, so 4–9 solves with the old factor give the step's δ where a factorisation costs about
// twenty. Measured on the armadillo's 1,978-edge hole (155,000 patch vertices, 15 steps, 4 of them
// by conjugate gradients): flow 31.6 / 32.1 s -> 28.2 / 28.6 s in two paired runs, the same patch.
// The old factor is tried after large moves too (it once was not, after a move of an edge length
// or more): the iteration count decides, and on 184,000 rows 11 iterations cost 0.7 s where a
// factorisation costs 1.0 s. Fill of the armadillo's 794-edge hole 3.41 -> 2.52 s (one run each).
// From this many rows on, an earlier factorisation is tried first; below, every step factorises.
// It was kCholmodMinRows (2,000): the elephant's 200-edge hole (1,522 free vertices, SimplicialLDLT)
// then factorised at every step, and its flow took 80-81 ms; with the old factor tried first,
// 69-76 ms (four paired runs, the same patch: 1,522 new vertices, 25.12°, E 26.432). 500 is not
// tuned: it lies below the patches measured.
constexpr int kPreconditionFromRows = 500;

// The culprits of an energy rise: the vertices whose energy rose most, until they make up this
// many times the rise. On the armadillo's 1,978-edge hole 1.25 still left 23 attempts of its
// coarse flow rejected in a row (the worst vertex rose by 1.2 where the step rose by 1.4), 1.0
// none.
constexpr double kCoverRise = 1.0;

}  // namespace

// The rows follow the state's connectivity; after edge flips the last factorisation stays, as a
// preconditioner (StepRows::update).
void SemiImplicitIntegrator::buildRows(const FlowState& state) { rows_.update(state, true); }

bool SemiImplicitIntegrator::solve() {
  StepSolver& s = *rows_.solver;
  return s.spd.solveStep(s.system.matrix(), s.system.rhs(), delta_, kPreconditionFromRows);
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

  // (M_ff + τ/2 · C_fa M_aa⁻¹ C_af) δ_f = τ M_ff F_f: to leading order F(P + δN) ≈ F − ½Δ_B²δ,
  // so the stiff fourth-order part is taken at the new time and everything else is lagged.
  rows_.solver->system.assemble(topo, geo, state.roles().active, rows_.index, n, speed_, tau);
  saved_ = positions;
  if (!solve()) return reject();
  const Eigen::VectorXd& delta = delta_;

  const double energyBefore = state.energy();
  const double energyLimit = energyBefore * (1 + kEnergySlack) + 1e-12;
  faceNormalBefore_ = geo.faceNormal;
  noteVertexEnergies(state, vertexEnergyBefore_);
  // The largest jump, as a multiple of what InternalFlowOptions::maxJump allows at its vertex.
  double overshoot = 0;
  for (int v = 0; v < nv; ++v) {
    const int r = rows_.index[v];
    if (r < 0) continue;
    if (!std::isfinite(delta[r])) return reject();
    double ring = 0;
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k)
      ring += (saved_[topo.ringVertex(k)] - saved_[v]).norm();
    const double allowed = state.internalOptions().maxJump * ring / std::max(1, topo.valence(v));
    if (delta[r] != 0) overshoot = std::max(overshoot, std::abs(delta[r]) / allowed);
  }
  if (!std::isfinite(overshoot)) return reject();  // a vertex whose edges have no length moves
  lastStepShortened_ = overshoot > 1;
  if (lastStepShortened_ && !state.internalOptions().shortenJumps) return reject();
  const double scale = lastStepShortened_ ? 1 / overshoot : 1.0;
  for (int v = 0; v < nv; ++v) {
    const int r = rows_.index[v];
    if (r >= 0) positions[v] += scale * delta[r] * geo.vertexNormal[v];
  }
  state.invalidate();
  // A failed check that a few vertices account for: those go back to where they were (held_),
  // the rest of the step stays, and the step is judged again.
  // Faces that would cross are held the same way (their free corners and rings): a region pressed
  // against a fold of its scan at its rim flows on elsewhere, where refusing the whole step held it
  // at tiny steps for the same few faces (docs/decisions.md, "Regions": held faces).
  held_.assign(nv, 0);
  for (int round = 0;; ++round) {
    if (acceptable(state, energyLimit)) {
      if (!guardEmbedding_) break;
      const std::vector<int> crossing = crossing_.crossingFaces(state.mesh(), state.roles().activeFace);
      if (crossing.empty()) break;
      if (round == kMaxHoldRounds || !holdCorners(state, crossing)) {
        ++crossingRejections_;
        return reject();
      }
    } else if (round == kMaxHoldRounds || !holdCulprits(state, energyBefore, energyLimit)) {
      return reject();
    }
    for (int v = 0; v < nv; ++v)
      if (held_[v]) positions[v] = saved_[v];
    state.invalidate();
  }
  double largest = 0;
  for (int v = 0; v < nv; ++v)
    if (rows_.index[v] >= 0 && !held_[v]) largest = std::max(largest, scale * std::abs(delta[rows_.index[v]]));
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
  if (guardEmbedding_) stepped_ = positions;
  bool drifted = false;
  for (int pass = 0; pass < opt.driftPasses && opt.tangentialDrift; ++pass) {
    if (!driftPass(state, energyLimit)) break;
    drifted = true;
  }
  // The step itself passed the embedding guard; drift passes that make faces cross are undone.
  if (drifted && guardEmbedding_ && crossing_.crosses(state.mesh(), state.roles().activeFace)) {
    positions = stepped_;
    state.invalidate();
  }
  // The last evaluation (of the accepted state) stays valid unless the boundary slides.
  state.slideBoundary();
  return true;
}

bool SemiImplicitIntegrator::acceptable(FlowState& state, double energyLimit) {
  const Geometry& geo = state.geometryOnly();
  const std::vector<std::uint8_t>& activeFace = state.roles().activeFace;
  for (int f = 0; f < state.topology().faceCount(); ++f)
    if (activeFace[f] && turnedOver(geo, f)) return false;
  const double e = state.energy();
  if (!std::isfinite(e)) return false;
  // The Laplacian-of-H flow is not a descent of E: it is judged by not creating folds only.
  return state.options().flow != FlowType::Elastica || e <= energyLimit;
}

void SemiImplicitIntegrator::noteVertexEnergies(FlowState& state, std::vector<double>& out) {
  state.energy();  // evaluates the curvature
  const Topology& topo = state.topology();
  const Geometry& geo = state.geometry();
  const Curvature& curv = state.curvature();
  const std::vector<std::uint8_t>& active = state.roles().active;
  out.assign(topo.vertexCount(), 0.0);
  parallelFor(topo.vertexCount(), [&](int i) {
    if (active[i]) out[i] = vertexCurvatureEnergy(topo, geo, curv, i);
  });
}

bool SemiImplicitIntegrator::holdCulprits(FlowState& state, double energyBefore, double energyLimit) {
  const Topology& topo = state.topology();
  const std::vector<Face>& faces = state.mesh().faces;
  culprits_.clear();
  // Faces that turned over: their corners (a face's normal depends on them alone).
  const Geometry& geo = state.geometryOnly();
  const std::vector<std::uint8_t>& activeFace = state.roles().activeFace;
  for (int f = 0; f < topo.faceCount(); ++f) {
    if (!activeFace[f] || !turnedOver(geo, f)) continue;
    if (static_cast<int>(culprits_.size()) + 3 > kMaxCulprits) return false;  // a step too large, not a few faces
    for (int v : faces[f]) culprits_.push_back(v);
  }
  // The vertices whose energy rose most, until they account for the whole rise (without their
  // moves, and their rings', the step would not have raised E, to first order).
  const double energy = state.energy();
  if (!std::isfinite(energy)) return false;
  if (state.options().flow == FlowType::Elastica && energy > energyLimit) {
    noteVertexEnergies(state, vertexEnergyAfter_);
    rises_.clear();
    for (int v = 0; v < topo.vertexCount(); ++v) {
      const double rise = vertexEnergyAfter_[v] - vertexEnergyBefore_[v];
      if (rise > 0) rises_.emplace_back(rise, v);
    }
    const int take = std::min<int>(kMaxCulprits + 1, static_cast<int>(rises_.size()));
    std::partial_sort(rises_.begin(), rises_.begin() + take, rises_.end(), std::greater<>());
    const double needed = kCoverRise * (energy - energyBefore);
    double covered = 0;
    for (int k = 0; k < take && covered < needed; ++k) {
      covered += rises_[k].first;
      culprits_.push_back(rises_[k].second);
    }
    if (covered < needed || static_cast<int>(culprits_.size()) > kMaxCulprits) return false;  // spread out
  }
  // A vertex's energy follows its own position and its ring's: hold the free ones of both.
  return holdCulpritsAndRings(state);
}

bool SemiImplicitIntegrator::holdCorners(FlowState& state, const std::vector<int>& faces) {
  const std::vector<std::uint8_t>& free = state.roles().free;
  culprits_.clear();
  for (int f : faces)
    for (int v : state.mesh().faces[f])
      if (free[v]) culprits_.push_back(v);
  if (static_cast<int>(culprits_.size()) > kMaxContactCulprits) return false;  // a step too large, not a contact
  return holdCulpritsAndRings(state);
}

bool SemiImplicitIntegrator::holdCulpritsAndRings(FlowState& state) {
  const Topology& topo = state.topology();
  const std::vector<std::uint8_t>& free = state.roles().free;
  bool more = false;
  auto hold = [&](int v) {
    if (free[v] && !held_[v]) held_[v] = 1, more = true;
  };
  for (int c : culprits_) {
    hold(c);
    for (int k = topo.ringBegin(c); k < topo.ringEnd(c); ++k) hold(topo.ringVertex(k));
  }
  return more;
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
