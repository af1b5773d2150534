// SPDX-License-Identifier: GPL-3.0-or-later
// The fairing amount (FlowOptions::featureSize) under the vector scheme: the flow's principal part
// run as a linear filter. For a bump of wavelength λ on a surface that bends on a scale R ≫ λ, the
// elastica flow F = −Δ_B H − 2H(H² − K) is, to leading order, u_t = −½ Δ²u: it damps the bump like
// exp(−½ (2π/λ)⁴ t), and −2H(H² − K) adds terms of relative order (λ/R)². An amount F asks for the
// bumps smaller than F to go and the shapes larger than F to stay, so the run takes the principal
// part alone, with the mesh's operators as it came:
//   (M + τ/2 · C M⁻¹ C) δ = −τ/2 · C M⁻¹ C X,   C the cotangent matrix, M the mixed vertex areas,
// factorised once and solved for each step (x, y and z). Where every active vertex is free (a whole
// closed mesh) the matrix is not assembled: A⁻¹ b = Re[(M + i s C)⁻¹ b], s² = τ/2, exactly, and
// the complex symmetric one-ring matrix is factorised instead (flow/complex_symmetric_ldlt.h), with
// a quarter to a third of the two-ring factor's fill. Elsewhere (fixed or sliding vertices), from
// 20,000 rows the steps are first solved by conjugate gradients with the two-ring matrix's incomplete
// Cholesky factor (flow/incomplete_cholesky_cg.h), and it is factorised only where they fall
// behind. Over the amount's time a sphere of
// radius R shrinks by 4 ln(100) R (F / 2πR)⁴: 1.4e-6 R when F is 3 % of its bounding-box diagonal.
// Why not the full flow: on a scan with 3-D vertex noise the nonlinear terms read the noise as
// curvature of order 1/ℓ, and the vector scheme's steps had to untangle the mesh first; the result
// ended farther from the clean scan than the noisy input (libcgal-demo bull, noise of 0.2 edge,
// F 1 %: RMS 1.18e-3 / 1.17e-3 of the diagonal against the input's 7.6e-4 / 6.5e-4); this filter
// brings it to 6.4e-4 / 6.7e-4 at F 1.5 % (docs/benchmarks.md, "Denoising against MeshLab").
// Recomputing the operators at each step on such a mesh made its weights wild (non-finite
// positions on the dino at noise 0.2 edge, F 3 %).
#pragma once

#include "flow/flow_state.h"

#include <elastica/flow.h>

#include <memory>
#include <vector>

namespace elastica {

class PrincipalPartFilter {
 public:
  PrincipalPartFilter();
  ~PrincipalPartFilter();
  PrincipalPartFilter(const PrincipalPartFilter&) = delete;
  PrincipalPartFilter& operator=(const PrincipalPartFilter&) = delete;

  /// Builds and factorises the step's matrix for step `tau` from `state`'s geometry now: the
  /// operators of every later step(). Fixed and sliding vertices stay where they are (their
  /// positions enter as data). `operators` Graph: uniform ones instead of the cotangents
  /// (flow/amount_operators.h). False if the matrix is not numerically positive definite.
  /// Frees `state`'s caches before it factorises, and step() before it solves (FlowState::releaseCaches).
  bool prepare(FlowState& state, double tau, AmountOperators operators = AmountOperators::Cotangent);
  /// One step: moves the free vertices of `state` (and invalidates its caches). False, with the
  /// positions unchanged, if a displacement is not finite.
  bool step(FlowState& state);
  /// Twicing's second pass (featureSizeStage): what the steps since `start` (the positions then)
  /// took away from the free vertices, filtered by `steps` more steps of the same factor, is added
  /// back. The filter is linear: x ← x + g(start − x). False, with the positions unchanged, if a
  /// displacement is not finite.
  bool addBackFilteredRemoval(FlowState& state, std::vector<Vec3> start, int steps);

 private:
  // One step on a field of the state's vertices (positions, or what a pass removed); the values
  // off the free vertices enter as data.
  bool stepField(const Topology& topo, std::vector<Vec3>& x);

  struct Solver;
  std::unique_ptr<Solver> solver_;
  std::vector<int> freeIndex_;
  std::vector<double> edgeWeight_, vertexArea_;  // the input's operators, for every step
  double tau_ = 0;
};

}  // namespace elastica
