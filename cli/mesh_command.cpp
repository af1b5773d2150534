// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh_command.h"

#include "mesh_files.h"

namespace elastica::cli {

CLI::App* addMeshCommand(CLI::App& app, const std::string& name, std::string& input, std::string& output,
                         const std::string& description, const std::string& inputFlags) {
  CLI::App* cmd = app.add_subcommand(name, description);
  cmd->add_option(inputFlags, input, "input mesh (.ply, .off, .stl, .obj)")->required();
  cmd->add_option("-o,--output", output, kOutputHelp)->required();
  return cmd;
}

}  // namespace elastica::cli
