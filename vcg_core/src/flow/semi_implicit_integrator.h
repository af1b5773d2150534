// SPDX-License-Identifier: GPL-3.0-or-later
// The semi-implicit scheme (ours; the paper's future work): linearly implicit in the stiff
// fourth-order part, (M + τ/2 C M⁻¹ C) δ = τ M F for the normal displacement δ, everything else
// lagged (semi_implicit_system.h). A step is accepted only if no active face turns over, no vertex
// jumps more than InternalFlowOptions::maxJump of its mean edge lengths, (elastica) the energy
// does not rise and, with the embedding guard on, no moved face crosses another; tangential drift
// passes follow under the same rules (the energy before the step as the limit).
#pragma once

#include "flow/flow_state.h"
#include "flow/step_rows.h"
#include "flow/tangential.h"
#include "mesh/crossing_cache.h"

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace elastica {

class SemiImplicitIntegrator {
 public:
  /// One attempt with step `tau`. On success the positions move, drift passes follow, and it
  /// returns true; if the step fails (the energy rises, a face flips, a vertex jumps, a value is
  /// non-finite) the positions are unchanged and it returns false.
  bool tryStep(FlowState& state, double tau);
  /// The largest normal displacement |δ_i| of the last accepted step.
  double lastNormalStep() const { return lastNormalStep_; }
  /// How much the last accepted step's normal displacement lowered the energy (its drift passes
  /// not counted: they even out triangles and may move E either way).
  double lastEnergyDecrease() const { return lastEnergyDecrease_; }
  /// Whether the last attempt would have moved a vertex farther than InternalFlowOptions::maxJump
  /// (with InternalFlowOptions::shortenJumps, the accepted step was shortened to it).
  bool lastStepShortened() const { return lastStepShortened_; }
  /// Keeps active faces from crossing other faces (mesh/self_intersection.h): the free corners of
  /// faces a step would make cross are held where they were (with their rings), as holdCulprits
  /// does, and the step is refused if that does not free it; drift passes that make faces cross
  /// are undone. Off by default: an input whose faces already cross has nothing to keep.
  void guardEmbedding(bool on) { guardEmbedding_ = on; }
  /// Attempts rejected by the embedding guard alone.
  long long crossingRejections() const { return crossingRejections_; }

 private:
  void speed(FlowState& state);
  void buildRows(const FlowState& state);
  /// δ for the assembled system (into delta_); false if the matrix does not factor.
  bool solve();
  /// Whether face f's normal turned against faceNormalBefore_ (the normals before the step).
  bool turnedOver(const Geometry& geo, int f) const { return geo.faceNormal[f].dot(faceNormalBefore_[f]) < 0; }
  /// Evaluates the moved positions: no active face turned over since faceNormalBefore_, finite
  /// energy, at most `energyLimit` (elastica).
  bool acceptable(FlowState& state, double energyLimit);
  /// One tangential drift pass; undone (returns false) if the result is not acceptable().
  bool driftPass(FlowState& state, double energyLimit);
  /// Each active vertex's term of the energy (vertexCurvatureEnergy) at the state's positions.
  void noteVertexEnergies(FlowState& state, std::vector<double>& out);
  /// After acceptable() said no to a step: if a few vertices account for it (the corners of the
  /// faces that turned over; the vertices whose energy rose most, until they make up the rise),
  /// holds them and their rings' free vertices in held_ and returns true; false if the
  /// failure is spread over more than kMaxCulprits vertices (the step is too large: halve τ) or
  /// nothing new would be held. A step is rejected at every τ when its stiffest local mode is
  /// mispredicted: the armadillo's 1,978-edge hole (coarse flow) lost 24 attempts in a row, τ
  /// halved from 4·10⁶ to 0.3 ℓ⁴, because a valence-4 patch vertex beside a fixed vertex with a
  /// large angle deficit (its energy term −4.8 of the patch's 119) raised its energy by 0.65 for a
  /// move of 0.015 ℓ, at every τ.
  bool holdCulprits(FlowState& state, double energyBefore, double energyLimit);
  /// The free corners of `faces` (about to cross) and their rings' free vertices into held_; false
  /// if more than kMaxContactCulprits corners or nothing new would be held.
  bool holdCorners(FlowState& state, const std::vector<int>& faces);
  /// culprits_ and their rings' free vertices into held_; false if nothing new would be held.
  bool holdCulpritsAndRings(FlowState& state);

  double lastNormalStep_ = 0, lastEnergyDecrease_ = 0;
  bool lastStepShortened_ = false;
  bool guardEmbedding_ = false;
  long long crossingRejections_ = 0;
  StepRows rows_;  // the free vertices' rows, the system and its factorisation
  Eigen::VectorXd delta_;
  std::vector<double> lh_, speed_;
  std::vector<Vec3> saved_, driftSaved_, faceNormalBefore_, drift_, stepped_;
  CrossingCache crossing_;  // the embedding guard's test, its fixed faces binned once
  std::vector<double> vertexEnergyBefore_, vertexEnergyAfter_;
  std::vector<std::uint8_t> held_;  // free vertices the current attempt keeps in place
  std::vector<int> culprits_;
  std::vector<std::pair<double, int>> rises_;
  DriftScratch driftScratch_;
};

}  // namespace elastica
