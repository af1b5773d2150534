// Fairing a mesh with a flow: the coarse-to-fine schedule (flow to near steady state, 1-to-4
// subdivision, flow again), the stopping rules and the safety net.
#pragma once

#include <elastica/flow.h>
#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Fairs `mesh` in place with `opt.flow`.
///
/// `faceSelected` (optional; one byte per face, non-zero = selected) restricts the flow to the
/// vertices whose faces are all selected; the rest never move, bit for bit. When subdividing, the
/// mesh and the selection are refined together (children inherit their parent's flag).
///
/// Stops at the energy plateau (FlowOptions::energyTolerance), or at maxSteps / maxSeconds, or
/// when the progress callback cancels; the report says which.
///
/// @throws InvalidInputError if the options are invalid, nothing can move, or a sliver would make
///         the explicit step vanish; the mesh is then unchanged.
/// @throws FlowDivergedError (a NumericalError, carrying the report so far) if the flow diverges
///         (non-finite positions, an energy blow-up, the mesh size running away); the mesh is then
///         left in the last good state checked (at most checkInterval steps back).
FlowReport fair(TriMesh& mesh, std::vector<std::uint8_t>* faceSelected, const FlowOptions& opt);

}  // namespace elastica
