// Command-line options of the commands that run a flow (fair and fill):
// they fill one FlowOptions, the same struct the MeshLab plugin fills from its dialog.
#pragma once

#include <elastica/app/filter_spec.h>
#include <elastica/flow.h>

#include <CLI/CLI.hpp>

namespace elastica::cli {

/// A check of a number against the range the application layer declares for a filter parameter
/// (app/filter_spec.h), so a flag and its MeshLab parameter accept the same values.
CLI::Validator parameterRange(app::FilterId filter, const std::string& parameter);

/// Registers what every flow run honours: --flow, --scheme, --max-steps, --max-seconds,
/// --energy-tol, --shape-tol, --no-tangential, --h2k, --area and --step-factor, writing into `opt`.
/// Choices are the application layer's names (app/choices.h).
void addFlowOptions(CLI::App& cmd, FlowOptions& opt);

/// Registers what only a flow over a whole mesh or region honours (not a hole's patch, whose
/// surroundings are fixed and whose faces must not be split): --subdivide, --target-edge,
/// --remesh, --boundary.
void addWholeMeshFlowOptions(CLI::App& cmd, FlowOptions& opt);

}  // namespace elastica::cli
