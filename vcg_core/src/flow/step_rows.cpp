// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/step_rows.h"

namespace elastica {

void StepRows::update(const FlowState& state, bool keepFactor) {
  if (version_ == state.connectivityVersion()) return;
  const int nv = state.topology().vertexCount();
  std::vector<int> rows(nv, -1);
  int row = 0;
  for (int v = 0; v < nv; ++v)
    if (state.roles().free[v]) rows[v] = row++;
  if (keepFactor && solver && rows == index) {
    solver->system.reset();
    solver->spd.patternChanged();
  } else {
    solver = std::make_shared<StepSolver>();
  }
  index.swap(rows);
  count = row;
  version_ = state.connectivityVersion();
}

}  // namespace elastica
