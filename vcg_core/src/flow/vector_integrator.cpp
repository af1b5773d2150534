// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/step_holds.h"
#include "flow/vector_integrator.h"
#include "support/parallel.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace elastica {
namespace {

// W may rise by this much (relative) and the step still count as not rising: rounding in a sum of
// thousands of terms, no more. The step is an exact descent direction, so no noise floor needs a
// wider margin (the normal-only scheme's lagged speed needed 1e-4).
constexpr double kEnergySlack = 1e-9;
// The curvature stiffness: kCurvatureStiffness · τ · Σ_edges max(C_ij, 0) · ½(H_i² + H_j²) |δ_i − δ_j|²
// added to the matrix. W's Hessian has, beside the bending part ½ C M⁻¹ C (k⁴ in a mode of wave
// number k), a part of order H² k² (the linearised −2H(H² − K) and the coupling of tangential
// moves to the normal curvature on a curved surface) that the plane's Hessian lacks; without it a
// step at the scale of the shape overshoots and W rises. It only preconditions: δ = 0 exactly
// where ∂W/∂X = 0, whatever the matrix. Measured (attempts of fair with this scheme, one run each,
// with a trace build): 96×32 torus 312 → 30, cow 136 → 98, 48×16 torus 622 (stalled) → 27 for
// 0 → 8; at 16 the cow stopped at E 78 under the energy-rate stop this scheme first had. With
// VectorIntegrator::saddleStiffness the H² is H² + max(0, −K): on a saddle (a handle's tunnel,
// H ≈ 0, K < 0) the principal curvatures are ±√−K, which H² alone does not see.
constexpr double kCurvatureStiffness = 8;
// From this many rows on, a step is first solved by conjugate gradients preconditioned with an
// earlier step's factorisation (SpdSolver::solveStep; the semi-implicit scheme does so from 500
// rows): a step's matrix differs from the last one by its τ (×2 or ×0.5) and the geometry's small
// change. Below, every step has its own factorisation, as before this reuse: there it costs
// little. On the 163,842-vertex noisy icosphere's full-size stage (143,634 vertices, coarse start)
// the second and third steps took 2 iterations each, 0.28 s, where the first step's factorisation
// took 1.2 s after a 1.5 s analysis (one quiet run).
constexpr int kPreconditionFromRows = 20000;
// An accepted step is carried on along its direction to at most this many times its length while
// W keeps falling (VectorIntegrator::tryStep).
constexpr double kMaxExtrapolation = 8;
// VectorIntegrator::dampOvershoots: μ of a vertex that overshot for the first time, its growth each
// time it overshoots again, and its decay after a step that needed no vertex held (μ below
// kDampingStart is dropped).
constexpr double kDampingStart = 1, kDampingGrow = 4, kDampingDecay = 0.5;
// VectorIntegrator::strainJumpLimit: the strain |δ_i − δ_j| / |X_i − X_j| of an edge that one step
// may reach where it moves a vertex beyond its own jump limit: steps up to that strain still lower
// W on a large selection (docs/decisions.md, "Regions").
constexpr double kMaxStepStrain = 0.5;
// VectorIntegrator::quasiNewton: how many secant pairs (accepted steps) the direction remembers.
constexpr int kSecantMemory = 5;

}  // namespace

VectorIntegrator::VectorIntegrator() : secant_(kSecantMemory) {}

void VectorIntegrator::buildRows(const FlowState& state) { rows_.update(state, false); }

Eigen::MatrixXd VectorIntegrator::freeRows(const std::vector<Vec3>& values) const {
  Eigen::MatrixXd rows(rows_.count, 3);
  for (std::size_t v = 0; v < rows_.index.size(); ++v)
    if (rows_.index[v] >= 0) rows.row(rows_.index[v]) = values[v].transpose();
  return rows;
}

bool VectorIntegrator::solveRows(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x) {
  return rows_.solver->spd.solveStep(rows_.solver->system.matrix(), rhs, x, kPreconditionFromRows);
}

// δ = −H·∂W/∂X: the plain step (H = H₀ = τ/4 · K⁻¹) or, with quasiNewton and pairs, L-BFGS's H.
// An accelerated direction that is not a descent one (rounding, a conjugate-gradient solve's
// inexact H₀) gives way to the plain step, and the pairs are dropped.
bool VectorIntegrator::solve(const std::vector<Vec3>& gradient, double tau) {
  const Eigen::MatrixXd g = freeRows(gradient);
  auto applyH0 = [&](const Eigen::MatrixXd& q, Eigen::MatrixXd& out) { return solveRows(0.25 * tau * q, out); };
  Eigen::MatrixXd hg;
  lastStepAccelerated_ = false;
  if (quasiNewton_ && tau >= quasiNewtonFrom_ && !secant_.empty()) {
    if (secant_.apply(g, applyH0, hg) && frobeniusDot(g, hg) > 0 && hg.allFinite()) lastStepAccelerated_ = true;
    else secant_.clear();
  }
  if (!lastStepAccelerated_ && !applyH0(g, hg)) return false;
  delta_.assign(rows_.index.size(), Vec3::Zero());
  for (std::size_t v = 0; v < rows_.index.size(); ++v)
    if (rows_.index[v] >= 0) delta_[v] = -hg.row(rows_.index[v]).transpose();
  return true;
}

// The pair of the last accepted step: s its change of the free positions, y the change of ∂W/∂X
// across it (at this attempt's start, after the step and the edge flips that followed it). The
// flips change W's discretisation after nearly every step of a region's tail, so y carries the
// flipped edges' terms too; taking y again on the flipped mesh (∂W/∂X at the step's start once
// more) reached the same energies in as many attempts (docs/decisions.md,
// "Regions"), so the pairs are kept across flips as they are. Pairs are kept only while the free
// vertices are the same ones (a stage's integrator is new after a remeshing).
void VectorIntegrator::addSecantPair(const FlowState& state, const Eigen::MatrixXd& gradient) {
  const Eigen::MatrixXd x = freeRows(state.mesh().positions);
  const bool sameVertices = previousFree_ == state.roles().free && previousX_.rows() == x.rows();
  if (!sameVertices) secant_.clear();
  if (pairPending_ && sameVertices) secant_.add(x - previousX_, gradient - previousGradient_);
  previousX_ = x;
  previousGradient_ = gradient;
  previousFree_ = state.roles().free;
  pairPending_ = false;
}

// The needle barrier's stiffness (bending_energy.h), which the bending matrix lacks: at a corner
// below 10° the barrier's second derivative grows as 1/θ⁴, and a step that ignores it overshoots
// the barrier and raises W at any τ above ~10⁻⁴ ℓ⁴: without it a scan's regions crawled at steps far
// below their shape time (docs/decisions.md, "Regions"). Added as an edge Laplacian on the two edges at the corner,
// weight (d²b/dθ²) / ℓ² (a far corner moving δ across an edge of length ℓ turns the angle by
// δ/ℓ), in the matrix's units (τ/4 of W's Hessian). It only preconditions: δ = 0 exactly where
// ∂W/∂X = 0.
bool VectorIntegrator::addBarrierStiffness(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                                           const std::vector<std::uint8_t>& activeFace, double tau) {
  edgeScratch_.assign(topo.edgeCount(), 0.0);
  bool any = false;
  cornerEdge_.assign(3 * static_cast<std::size_t>(topo.faceCount()), -1);
  for (int e = 0; e < topo.edgeCount(); ++e)
    for (int c : topo.edgeOppositeCorners(e))
      if (c >= 0) cornerEdge_[c] = e;
  for (int f = 0; f < topo.faceCount(); ++f) {
    if (!activeFace[f] || !(geo.faceArea[f] > 0)) continue;
    for (int k = 0; k < 3; ++k) {
      const std::size_t c = 3 * static_cast<std::size_t>(f) + k;
      const double stiffness = needleBarrierStiffness(geo.cornerDot[c] / (2 * geo.faceArea[f]));
      if (stiffness == 0) continue;
      for (int side = 1; side <= 2; ++side) {  // the edges at corner k are opposite corners k + 1, k + 2
        const int e = cornerEdge_[3 * static_cast<std::size_t>(f) + (k + side) % 3];
        const auto& ev = topo.edgeVertices(e);
        const double length2 = (p[ev[0]] - p[ev[1]]).squaredNorm();
        if (length2 > 0) edgeScratch_[e] += stiffness / length2, any = true;
      }
    }
  }
  if (any) rows_.solver->system.addEdgeLaplacian(topo, edgeScratch_, rows_.index, 0.25 * tau);
  return any;
}

// The first try's culprits of the current attempt, and their rings, get their μ raised.
void VectorIntegrator::dampOvershoot(const Topology& topo) {
  if (!dampOvershoots_ || overshot_.empty()) return;
  raised_.assign(damping_.size(), 0);
  auto raise = [&](int v) {
    if (raised_[v]) return;
    raised_[v] = 1;
    damping_[v] = std::max(kDampingStart, damping_[v] * kDampingGrow);
  };
  for (int c : overshot_) {
    raise(c);
    for (int k = topo.ringBegin(c); k < topo.ringEnd(c); ++k) raise(topo.ringVertex(k));
  }
}

void VectorIntegrator::relaxDamping() {
  for (double& mu : damping_) mu = mu < kDampingStart ? 0 : mu * kDampingDecay;
}

// How far the solved step δ goes beyond the jump limit (a factor; above 1 the step is shortened by
// it). No vertex moves farther than InternalFlowOptions::maxJump of its own ring's mean edge; with
// strainJumpLimit a step beyond that passes if no edge strains by more than kMaxStepStrain, and is
// else shortened to the larger of the two lengths.
double VectorIntegrator::jumpOvershoot(const FlowState& state) const {
  const Topology& topo = state.topology();
  double overshoot = 0;
  for (int v = 0; v < topo.vertexCount(); ++v) {
    if (rows_.index[v] < 0) continue;
    const double move = delta_[v].norm();
    if (!std::isfinite(move)) return move;
    double ring = 0;
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) ring += (saved_[topo.ringVertex(k)] - saved_[v]).norm();
    const double allowed = state.internalOptions().maxJump * ring / std::max(1, topo.valence(v));
    if (move > 0) overshoot = std::max(overshoot, move / allowed);
  }
  if (!strainJumpLimit_ || overshoot <= 1) return overshoot;
  double strain = 0;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& ev = topo.edgeVertices(e);
    if (rows_.index[ev[0]] < 0 && rows_.index[ev[1]] < 0) continue;
    const double stretch = (delta_[ev[0]] - delta_[ev[1]]).norm();
    if (stretch > 0) strain = std::max(strain, stretch / (kMaxStepStrain * (saved_[ev[0]] - saved_[ev[1]]).norm()));
  }
  return std::min(overshoot, strain);
}

// The attempt's start: ∂W/∂X and W at the current positions, and the last accepted step's pair.
void VectorIntegrator::evaluateStart(FlowState& state, const Geometry& geo) {
  bendingGradient(state.topology(), geo, state.positions(), state.roles().active, bending_);
  ++gradientEvaluations_;
  if (quasiNewton_) addSecantPair(state, freeRows(bending_.gradient));
  startEnergy_ = bending_.value;
  termBefore_ = bending_.term;
}

// The step's matrix: M + τ/2 · C M⁻¹ C, the curvature stiffness, with `barrierStiffness` the
// needle barrier's, and the damped rows' 1 + μ. Returns whether the barrier's stiffness was added.
bool VectorIntegrator::assembleMatrix(FlowState& state, const Geometry& geo, const Curvature& curv, double tau,
                                      bool barrierStiffness) {
  const Topology& topo = state.topology();
  rows_.solver->system.assembleMatrix(topo, geo.edgeWeight, geo.vertexArea, state.roles().active, rows_.index,
                                      state.roles().freeCount, 1.0, 0.5 * tau);
  edgeScratch_.resize(topo.edgeCount());
  auto bend = [&](int v) { return curv.H[v] * curv.H[v] + (saddleStiffness_ ? std::max(0.0, -curv.K[v]) : 0.0); };
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& ev = topo.edgeVertices(e);
    const double h2 = 0.5 * (bend(ev[0]) + bend(ev[1]));
    edgeScratch_[e] = std::max(geo.edgeWeight[e], 0.0) * h2;
  }
  rows_.solver->system.addEdgeLaplacian(topo, edgeScratch_, rows_.index, kCurvatureStiffness * tau);
  const bool withBarrier =
      barrierStiffness && addBarrierStiffness(topo, geo, state.positions(), state.roles().activeFace, tau);
  for (int v = 0; v < topo.vertexCount(); ++v)
    if (rows_.index[v] >= 0 && damping_[v] > 0) rows_.solver->system.scaleDiagonal(rows_.index[v], 1 + damping_[v]);
  return withBarrier;
}

// A refused attempt: the positions go back to the attempt's start.
bool VectorIntegrator::rejectAttempt(FlowState& state, double tau) {
  pairPending_ = false;
  if (lastStepAccelerated_) {
    // The pairs' model misled the step (W rose, faces turned or crossed, too many vertices to
    // hold): the same attempt goes on with the plain step, whose refusal alone is the
    // controller's business (τ halved, culprits damped); with no pairs left it is plain. The
    // retry starts from the same positions, so it keeps the attempt's gradient and matrix.
    if (lastRejectionCrossed_) --crossingRejections_;
    ++acceleratedRefusals_;
    state.positions() = saved_;
    state.invalidate();
    secant_.clear();
    retryPlain_ = true;
    const bool accepted = tryStep(state, tau);
    retryPlain_ = false;
    return accepted;
  }
  secant_.clear();
  dampOvershoot(state.topology());
  state.positions() = saved_;
  state.invalidate();
  return false;
}

// The free vertices at the attempt's start moved by `alpha` times the solved step.
void VectorIntegrator::moveAlongStep(std::vector<Vec3>& positions, double alpha) const {
  for (std::size_t v = 0; v < rows_.index.size(); ++v)
    if (rows_.index[v] >= 0) positions[v] = saved_[v] + alpha * delta_[v];
}

// Every active face that turned over since the attempt's start has its corners added as culprits.
bool VectorIntegrator::addTurnedFaceCulprits(const Topology& topo, const std::vector<std::uint8_t>& activeFace,
                                             const Geometry& moved) {
  bool turned = false;
  for (int f = 0; f < topo.faceCount(); ++f) {
    if (!activeFace[f] || moved.faceNormal[f].dot(faceNormalBefore_[f]) >= 0) continue;
    turned = true;
    for (int v : topo.faces()[f]) culprits_.push_back(v);
  }
  return turned;
}

// Whether an active face turned over since the attempt's start.
bool VectorIntegrator::anyFaceTurned(const Topology& topo, const std::vector<std::uint8_t>& activeFace,
                                     const Geometry& moved) const {
  for (int f = 0; f < topo.faceCount(); ++f)
    if (activeFace[f] && moved.faceNormal[f].dot(faceNormalBefore_[f]) < 0) return true;
  return false;
}

// W rose by `rise`: the vertices whose terms rose most are culprits, until they make up the rise.
// False where they do not, or take more than kMaxCulprits.
bool VectorIntegrator::addRiseCulprits(int nv, double rise, int round) {
  rises_.clear();
  for (int v = 0; v < nv; ++v) {
    const double r = bending_.term[v] - termBefore_[v];
    if (r > 0) rises_.emplace_back(r, v);
  }
  const int take = std::min<int>(kMaxCulprits + 1, static_cast<int>(rises_.size()));
  std::partial_sort(rises_.begin(), rises_.begin() + take, rises_.end(), std::greater<>());
  double covered = 0;
  for (int k = 0; k < take && covered < rise; ++k) covered += rises_[k].first, culprits_.push_back(rises_[k].second);
  if (round == 0) overshot_ = culprits_;
  return !(covered < rise || static_cast<int>(culprits_.size()) > kMaxCulprits);
}

// The culprits' free vertices and their rings are held; false if none is newly held.
bool VectorIntegrator::holdCulprits(const Topology& topo) {
  bool more = false;
  auto hold = [&](int v) {
    if (rows_.index[v] >= 0 && !held_[v]) held_[v] = 1, more = true;
  };
  for (int c : culprits_) {
    hold(c);
    for (int k = topo.ringBegin(c); k < topo.ringEnd(c); ++k) hold(topo.ringVertex(k));
  }
  return more;
}

// The step `scale` · δ, tried with ever more vertices held (step_holds.h) until W does not rise,
// no face turns over and none crosses: true then (positions moved, energyAfter_ set), false where
// the attempt is refused.
bool VectorIntegrator::placeHeldStep(FlowState& state, double scale) {
  std::vector<Vec3>& positions = state.positions();
  const Topology& topo = state.topology();
  const std::vector<std::uint8_t>& active = state.roles().active;
  const std::vector<std::uint8_t>& activeFace = state.roles().activeFace;
  const double before = startEnergy_;
  const int nv = topo.vertexCount();
  held_.assign(nv, 0);
  for (int round = 0;; ++round) {
    for (int v = 0; v < nv; ++v)
      if (rows_.index[v] >= 0) positions[v] = held_[v] ? saved_[v] : Vec3(saved_[v] + scale * delta_[v]);
    state.invalidate();
    const Geometry& moved = state.geometryOnly();
    culprits_.clear();
    const bool turned = addTurnedFaceCulprits(topo, activeFace, moved);
    const double after = turned ? before : bendingEnergy(topo, moved, positions, active, bending_);
    if (!std::isfinite(after)) return false;
    const bool rose = after > before + kEnergySlack * std::abs(before);
    bool crossed = false;
    if (!turned && !rose) {
      // Faces that would cross: their free corners are held where they were (not crossing), and
      // the rest of the step goes on. A swelling limb that reaches the body stops there, and the
      // rest of the surface keeps flowing (homer: refusing such steps ended the run at E 193 after
      // 63 attempts; holding, it converged round in 51).
      if (guardEmbedding_)
        for (int f : crossing_.crossingFaces(state.mesh(), activeFace))
          for (int v : topo.faces()[f]) culprits_.push_back(v), crossed = true;
      if (!crossed) {
        energyAfter_ = after;
        return true;
      }
    }
    lastStepHeldContact_ = lastStepHeldContact_ || crossed;
    if (round == 0 && !crossed) overshot_ = culprits_;  // faces turned over (a contact is no overshoot)
    const int allowed = crossed ? kMaxContactCulprits : kMaxCulprits;
    if (round == kMaxHoldRounds || static_cast<int>(culprits_.size()) > allowed) {
      if (crossed) ++crossingRejections_, lastRejectionCrossed_ = true;
      return false;
    }
    if (rose && !addRiseCulprits(nv, after - before, round)) return false;
    if (!holdCulprits(topo)) return false;
  }
}

// A step the model of W's curvature made too short (W's Hessian is not the matrix): while W
// keeps falling, go on along the same direction, to kMaxExtrapolation times the step, within
// the jump limit. Each try costs an evaluation of W, no solve. On the elephant (genus 3) steps at
// τ ≫ T moved 0.15 ℓ each and lowered W by 0.03 each, for hundreds of steps.
void VectorIntegrator::extrapolate(FlowState& state, double overshoot, double scale) {
  std::vector<Vec3>& positions = state.positions();
  const Topology& topo = state.topology();
  const std::vector<std::uint8_t>& active = state.roles().active;
  const std::vector<std::uint8_t>& activeFace = state.roles().activeFace;
  double alpha = 1;
  const double limit = std::min(kMaxExtrapolation, overshoot > 0 ? 1 / overshoot : kMaxExtrapolation);
  while (2 * alpha <= limit) {
    const double trial = 2 * alpha;
    moveAlongStep(positions, trial);
    state.invalidate();
    const Geometry& moved = state.geometryOnly();
    const bool turned = anyFaceTurned(topo, activeFace, moved);
    const double w = turned ? energyAfter_ : bendingEnergy(topo, moved, positions, active, bending_);
    if (turned || !(w < energyAfter_)) break;
    alpha = trial;
    energyAfter_ = w;
  }
  moveAlongStep(positions, alpha);
  state.invalidate();
  if (alpha > 1 && guardEmbedding_ && crossing_.crosses(state.mesh(), activeFace)) {
    alpha = 1;  // the step itself passed the guard
    moveAlongStep(positions, scale);
    state.invalidate();
    energyAfter_ = bendingEnergy(topo, state.geometryOnly(), positions, active, bending_);
  }
  lastExtrapolation_ = alpha;
}

// An accepted step's record (its largest moves, W before it), the damping's update and the
// sliding border's move.
void VectorIntegrator::finishStep(FlowState& state) {
  const std::vector<Vec3>& positions = state.positions();
  double largest = 0, largestNormal = 0;
  for (std::size_t v = 0; v < rows_.index.size(); ++v) {
    if (rows_.index[v] < 0) continue;
    const Vec3 d = positions[v] - saved_[v];
    largest = std::max(largest, d.norm());
    largestNormal = std::max(largestNormal, std::abs(d.dot(normalBefore_[v])));
  }
  if (overshot_.empty()) relaxDamping();
  else dampOvershoot(state.topology());
  energyBefore_ = startEnergy_;
  lastMove_ = largest;
  lastNormalMove_ = largestNormal;
  state.slideBoundary();
  pairPending_ = true;
}

bool VectorIntegrator::tryStep(FlowState& state, double tau) {
  lastRejectionCrossed_ = false;
  lastStepHeldContact_ = false;
  lastExtrapolation_ = 1;
  const Geometry& geo = state.geometryOnly();
  buildRows(state);
  // The plain retry of a refused accelerated step (`retryPlain_`) starts where the first try did:
  // its gradient, W and matrix are the ones at hand.
  if (!retryPlain_) evaluateStart(state, geo);
  const int nv = state.topology().vertexCount();
  const Curvature& curv = state.curvature();
  if (static_cast<int>(damping_.size()) != nv) damping_.assign(nv, 0.0);  // a new mesh
  overshot_.clear();
  if (!retryPlain_) {
    withBarrier_ = assembleMatrix(state, geo, curv, tau, true);
    saved_ = state.positions();
    faceNormalBefore_ = geo.faceNormal;
    normalBefore_ = geo.vertexNormal;
  }
  // The barrier's stiffness at a step far beyond the shape's time scale can make the matrix too
  // ill-conditioned to factorise (pivots lost to rounding): the step is then solved without it.
  if (!solve(bending_.gradient, tau) &&
      !(withBarrier_ && (assembleMatrix(state, geo, curv, tau, false), solve(bending_.gradient, tau)))) {
    secant_.clear();
    return false;
  }
  // The jump limit (jumpOvershoot): a longer step is shortened (every displacement by the same
  // factor), which keeps it a descent direction.
  const double overshoot = jumpOvershoot(state);
  if (!std::isfinite(overshoot)) return lastStepAccelerated_ ? rejectAttempt(state, tau) : false;
  lastStepShortened_ = overshoot > 1;
  const double scale = lastStepShortened_ ? 1 / overshoot : 1.0;
  if (!placeHeldStep(state, scale)) return rejectAttempt(state, tau);
  const bool anyHeld = std::any_of(held_.begin(), held_.end(), [](std::uint8_t h) { return h != 0; });
  if (!anyHeld && !lastStepShortened_) extrapolate(state, overshoot, scale);
  finishStep(state);
  return true;
}

}  // namespace elastica
