// SPDX-License-Identifier: GPL-3.0-or-later
// Registering a mesh command (fair, fill, curvature, run, subdivide): its input and required -o
// are named and explained alike everywhere, so they are added in one place.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace elastica::cli {

/// Adds the subcommand `name` to `app` with its input mesh (the positional `input`, or the option
/// `inputFlags`, e.g. "-i,--input") and its required -o (kOutputHelp), both required.
CLI::App* addMeshCommand(CLI::App& app, const std::string& name, std::string& input, std::string& output,
                         const std::string& description, const std::string& inputFlags = "input");

}  // namespace elastica::cli
