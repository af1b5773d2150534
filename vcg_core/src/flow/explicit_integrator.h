// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's explicit scheme (eq. 2.2/2.3): one step moves every free vertex by τF along its
// normal, τ = stepFactor · A_min², plus the tangential drift ε·T (eq. 2.5); for the bilaplacian
// comparison flow, P ← P − τ U0²(P).
#pragma once

#include "flow/flow_state.h"
#include "flow/tangential.h"

#include <cstddef>
#include <vector>

namespace elastica {

class ExplicitIntegrator {
 public:
  /// One step on `state`; returns the flow time advanced. @throws NumericalError if a position
  /// became non-finite (positions then undefined: roll back); InvalidInputError if a sliver makes
  /// the step vanish.
  double step(FlowState& state);

  /// Bytes of this integrator's per-step arrays (Δ_B H, the drift and its scratch), for the
  /// benchmarks' memory-traffic reference (flow/working_set.h).
  std::size_t scratchBytes() const;

 private:
  double normalStep(FlowState& state);
  double bilaplacianStep(FlowState& state);

  std::vector<double> lh_;
  std::vector<Vec3> u_, drift_;
  DriftScratch driftScratch_;
};

}  // namespace elastica
