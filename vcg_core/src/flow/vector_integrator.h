// SPDX-License-Identifier: GPL-3.0-or-later
// The vector scheme (the default): a linearly implicit Euler step of the gradient flow of the
// discrete bending energy W (flow/bending_energy.h) with the positions themselves as unknowns,
//   (M + τ/2 · C M⁻¹ C) δ = −τ/4 · ∂W/∂X,   one factorisation, three right-hand sides (x, y, z),
// C, M, ∂W/∂X at the old positions. ∂W/∂X is the exact gradient of the energy the step is judged
// by, so the step is a descent direction at every τ and a small enough one always lowers W; the
// matrix is the energy's Hessian on a plane (½ C M⁻¹ C for W/4), so a step at the region's own
// scale (τ ≈ A²) relaxes every bending mode at once, as a Newton step would. The factor ¼ makes τ
// the paper's time (W = 4∫H² − 4πχ, and F = −Δ_B H − 2H(H² − K) is the L² gradient of −∫H²).
// The motion is not confined to the normals: vertices move tangentially wherever that lowers W,
// and W's tangential part (|Δ_B X|² beyond its normal component) evens the mesh out.
#pragma once

#include "flow/bending_energy.h"
#include "flow/flow_state.h"
#include "flow/secant_pairs.h"
#include "flow/step_rows.h"
#include "mesh/crossing_cache.h"

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace elastica {

class VectorIntegrator {
 public:
  VectorIntegrator();
  /// One attempt with step `tau`. On success the positions move and it returns true; if W rises,
  /// an active face turns over, a value is non-finite or (with the guard) faces cross, the
  /// positions are unchanged and it returns false.
  bool tryStep(FlowState& state, double tau);
  /// W before and after the last accepted step.
  double energyBefore() const { return energyBefore_; }
  double energyAfter() const { return energyAfter_; }
  /// The largest displacement |δ_i| of the last accepted step.
  double lastMove() const { return lastMove_; }
  /// The largest normal component |δ_i · N_i| of the last accepted step.
  double lastNormalMove() const { return lastNormalMove_; }
  /// Whether the last attempt was shortened to InternalFlowOptions::maxJump.
  bool lastStepShortened() const { return lastStepShortened_; }
  /// How far the last accepted step went along its solve's direction (1, or up to 8 when W kept
  /// falling beyond it).
  double lastExtrapolation() const { return lastExtrapolation_; }
  void guardEmbedding(bool on) { guardEmbedding_ = on; }
  /// The matrix's curvature stiffness reads the principal curvatures on saddles too (H² − K where
  /// K < 0, not H² alone). On a surface with handles, whose tunnels are saddles that stay, steps
  /// were refused at 1e-3 of the shape's relaxation time for hundreds of attempts (elephant:
  /// 411 → 217 attempts, joint 199 → 161); on genus 0, whose saddles flow away, the stiffer
  /// matrix only shortens the large steps (cow 87 → 184, bull 145 → 313): off there.
  void saddleStiffness(bool on) { saddleStiffness_ = on; }
  /// Marquardt's damping where the step's model overshoots: the vertices whose terms made a step's
  /// first try raise W (or whose faces turned over), and their rings, get their rows' diagonal
  /// multiplied by 1 + μ in the following solves (μ from 1, ×4 each time they overshoot again,
  /// halved after every step that needed no vertex held, dropped below 1). The matrix lacks W's
  /// nonlinearity there (a valence-3 or -4 vertex moving along the surface changes the cotangents
  /// of its ring), and without the damping the same few vertices raised every first try, so that
  /// the held retries and refusals kept τ far below the shape's time. Only preconditions: δ = 0
  /// exactly where ∂W/∂X = 0. Off on whole meshes, where the refusals end a stage held back by its
  /// mesh and the schedule remeshes it.
  void dampOvershoots(bool on) { dampOvershoots_ = on; }
  /// The jump limit asks whether a step strains the mesh, not only how far each vertex goes: a step
  /// that moves a vertex farther than InternalFlowOptions::maxJump of its own ring's mean edge
  /// still passes where no edge's ends move apart (or turn) by more than half its length. The
  /// per-vertex limit binds a region's every step to the scan's smallest triangles, where the
  /// region moves tens of edge lengths smoothly over them (a rigid motion strains nothing, and the
  /// step's model, W's matrix at the old positions, changes with the strain, not with the
  /// distance). On selections (docs/decisions.md, "Regions").
  void strainJumpLimit(bool on) { strainJumpLimit_ = on; }
  /// Preconditioned L-BFGS (flow/secant_pairs.h): the step's direction is H·∂W/∂X with H₀ the
  /// step's own solve (τ/4 · K⁻¹) corrected by the last accepted steps s and the changes y of ∂W/∂X
  /// across them. At τ far beyond the shape's time K is τ times a fixed matrix, the plain step is a
  /// preconditioned gradient descent on W with a frozen model of its Hessian, and it crawls
  /// (docs/benchmarks.md, "Regions beside CGAL's fair()": where a region's time goes). Only at τ ≥ fromTau (the shape's time T:
  /// below it H₀ scales with τ, the controller's step size, and the accelerated steps there were
  /// refused so often that τ stayed near T). The accelerated step passes the same checks as the
  /// plain one; where it fails, the pairs are dropped and the same attempt takes the plain step.
  void quasiNewton(bool on, double fromTau) { quasiNewton_ = on, quasiNewtonFrom_ = fromTau; }
  /// Whether the last attempt's direction used secant pairs (false: the plain step).
  bool lastStepAccelerated() const { return lastStepAccelerated_; }
  long long crossingRejections() const { return crossingRejections_; }
  /// Accelerated steps refused and taken again as the plain step in the same attempt.
  long long acceleratedRefusals() const { return acceleratedRefusals_; }
  /// Evaluations of ∂W/∂X: one per attempt (the plain retry keeps its attempt's).
  long long gradientEvaluations() const { return gradientEvaluations_; }
  /// Whether the last accepted step held vertices that would have made faces cross (a contact).
  bool lastStepHeldContact() const { return lastStepHeldContact_; }
  /// Whether the last attempt was rejected by the embedding guard alone.
  bool lastRejectionCrossed() const { return lastRejectionCrossed_; }

 private:
  void buildRows(const FlowState& state);
  double jumpOvershoot(const FlowState& state) const;
  void dampOvershoot(const Topology& topo);
  void relaxDamping();
  bool solve(const std::vector<Vec3>& gradient, double tau);
  bool solveRows(const Eigen::MatrixXd& rhs, Eigen::MatrixXd& x);
  Eigen::MatrixXd freeRows(const std::vector<Vec3>& values) const;
  void addSecantPair(const FlowState& state, const Eigen::MatrixXd& gradient);
  bool addBarrierStiffness(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                           const std::vector<std::uint8_t>& activeFace, double tau);
  // tryStep's parts, in the order it takes them.
  void evaluateStart(FlowState& state, const Geometry& geo);
  bool assembleMatrix(FlowState& state, const Geometry& geo, const Curvature& curv, double tau, bool barrierStiffness);
  bool placeHeldStep(FlowState& state, double scale);
  bool addTurnedFaceCulprits(const Topology& topo, const std::vector<std::uint8_t>& activeFace, const Geometry& moved);
  bool anyFaceTurned(const Topology& topo, const std::vector<std::uint8_t>& activeFace, const Geometry& moved) const;
  bool addRiseCulprits(int nv, double rise, int round);
  bool holdCulprits(const Topology& topo);
  void extrapolate(FlowState& state, double overshoot, double scale);
  void moveAlongStep(std::vector<Vec3>& positions, double alpha) const;
  void finishStep(FlowState& state);
  bool rejectAttempt(FlowState& state, double tau);

  double energyBefore_ = 0, energyAfter_ = 0, lastMove_ = 0, lastNormalMove_ = 0, lastExtrapolation_ = 1;
  bool lastStepShortened_ = false, guardEmbedding_ = false, saddleStiffness_ = false, lastRejectionCrossed_ = false, lastStepHeldContact_ = false;
  bool dampOvershoots_ = false, strainJumpLimit_ = false, quasiNewton_ = false, lastStepAccelerated_ = false;
  // tryStep's plain retry of a refused accelerated step, and what it keeps of the first try: W at
  // the attempt's start and whether its matrix has the barrier's stiffness.
  bool retryPlain_ = false, withBarrier_ = false;
  double startEnergy_ = 0;
  bool pairPending_ = false;  // the last attempt was accepted: its pair is formed at the next attempt's start
  long long crossingRejections_ = 0, acceleratedRefusals_ = 0, gradientEvaluations_ = 0;
  StepRows rows_;  // the free vertices' rows, the system and its factorisation
  double quasiNewtonFrom_ = 0;
  std::vector<double> edgeScratch_;
  std::vector<int> cornerEdge_;
  std::vector<Vec3> saved_, faceNormalBefore_, normalBefore_, delta_;
  std::vector<double> termBefore_;
  std::vector<std::uint8_t> held_;  // free vertices the current attempt keeps in place
  std::vector<double> damping_;     // per vertex: its μ (dampOvershoots), kept across attempts
  std::vector<int> overshot_;       // the current attempt's first-try culprits
  std::vector<std::uint8_t> raised_;
  std::vector<int> culprits_;
  std::vector<std::pair<double, int>> rises_;
  BendingEnergy bending_;
  SecantPairs secant_;
  Eigen::MatrixXd previousX_, previousGradient_;  // free rows at the last attempt's start
  std::vector<std::uint8_t> previousFree_;
  CrossingCache crossing_;  // the embedding guard's test, the fixed faces' grid kept across attempts
};

}  // namespace elastica
