// SPDX-License-Identifier: GPL-3.0-or-later
// The memory an explicit step reads or writes, for the benchmarks' bandwidth reference
// (bench/flow_bench.cpp): not part of any flow.
#pragma once

#include "flow/explicit_integrator.h"
#include "flow/flow_state.h"

#include <cstddef>

namespace elastica {

/// Bytes held by the arrays one explicit step touches (positions, topology, roles, geometry,
/// curvature and the integrator's scratch): the memory-traffic floor of a step if each were
/// touched once. Call after a step, when every cache is sized.
std::size_t explicitStepWorkingSetBytes(FlowState& state, const ExplicitIntegrator& integrator);

}  // namespace elastica
