// SPDX-License-Identifier: GPL-3.0-or-later
// Subcommands of the `elastica` program. Each registers itself on the CLI11 app with its options
// and a callback that does the work; main() turns exceptions into one line on stderr and an exit
// code.
#pragma once

#include <CLI/CLI.hpp>

namespace elastica::cli {

void addBatchCommand(CLI::App& app);
void addCurvatureCommand(CLI::App& app);
void addGenerateCommand(CLI::App& app);
void addFairCommand(CLI::App& app);
void addFillCommand(CLI::App& app);
void addRunCommand(CLI::App& app);
void addSubdivideCommand(CLI::App& app);

}  // namespace elastica::cli
