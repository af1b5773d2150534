// Command-line options shared by the commands that run a flow (fair, and later fill and run):
// they fill one FlowOptions, the same struct the MeshLab plugin fills from its dialog.
#pragma once

#include <elastica/flow.h>

#include <CLI/CLI.hpp>

namespace elastica::cli {

/// Registers --flow, --scheme, --subdivide, --target-edge, --max-steps, --max-seconds, --energy-tol,
/// --remesh, --no-tangential, --boundary, --h2k, --area and --step-factor on `cmd`, writing into `opt`.
void addFlowOptions(CLI::App& cmd, FlowOptions& opt);

}  // namespace elastica::cli
