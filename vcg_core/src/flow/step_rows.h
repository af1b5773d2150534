// SPDX-License-Identifier: GPL-3.0-or-later
// The unknowns of an integrator's linear step (one row per free vertex, in vertex order) and the
// system and factorisation solved for them, kept while the state's connectivity stays (the
// sparsity pattern follows it: flow/semi_implicit_system.h, flow/spd_solver.h).
#pragma once

#include "flow/flow_state.h"
#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"

#include <memory>
#include <vector>

namespace elastica {

struct StepSolver {
  SemiImplicitSystem system;
  SpdSolver spd;
};

class StepRows {
 public:
  /// Brings the rows up to the state's connectivity (nothing to do while it stays). After edge
  /// flips, which move no vertex, the free vertices are the same rows: with `keepFactor` the
  /// solver stays, its system forgetting its pattern and its factorisation kept to precondition
  /// the next solves (SpdSolver::patternChanged); otherwise, and for other rows, a new solver.
  void update(const FlowState& state, bool keepFactor);

  std::vector<int> index;  // vertex → row of the system, or −1
  int count = 0;
  std::shared_ptr<StepSolver> solver;

 private:
  long long version_ = -1;  // of the state that the rows and the solver were built for
};

}  // namespace elastica
