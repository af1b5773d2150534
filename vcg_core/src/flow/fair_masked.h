// SPDX-License-Identifier: GPL-3.0-or-later
// fair() on a selection given as one byte per face, in and out: what the public fair() overloads
// and the hole filler (which fairs a patch inside a submesh) share.
#pragma once

#include <elastica/flow.h>
#include <elastica/types.h>
#include "flow/internal_flow_options.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace elastica {

/// As fair(mesh, region, opt) with `*faceSelected` the region's flags (non-zero = in the region),
/// or as fair(mesh, opt) if faceSelected is null or empty. The flags are refined with the mesh
/// when it is subdivided (children inherit their parent's flag) and written back. `internal`: the
/// knobs no face sets (fair() passes the defaults, the hole filler its own). `stageEnded`, if
/// given, is called with the mesh and the flags as each stage of the schedule ends: fair(mesh,
/// region) keeps the last one that passes its output checks (flow/region_guard.h).
/// @throws InvalidInputError also if the flags are not one per face.
using StageEnded = std::function<void(const TriMesh&, const std::vector<std::uint8_t>&)>;
FlowReport fairMasked(TriMesh& mesh, std::vector<std::uint8_t>* faceSelected, const FlowOptions& opt,
                      const InternalFlowOptions& internal, const StageEnded& stageEnded = {});

/// @throws InvalidInputError if `opt` is not valid (what fair() checks before it starts).
void validateFlowOptions(const FlowOptions& opt);

}  // namespace elastica
