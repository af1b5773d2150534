// SPDX-License-Identifier: GPL-3.0-or-later
// Writing a JSON report (--report; app/reports.h builds it), and the live progress line on a terminal.
#pragma once

#include <elastica/flow.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace elastica::cli {

/// Writes `j` to `path` atomically. @throws IoError.
void writeJson(const std::string& path, const nlohmann::json& j);

/// --report after a written mesh: names `input` and `output` in `j`, writes it to `path` and says
/// so on stdout.
void writeReport(const std::string& path, nlohmann::json j, const std::string& input, const std::string& output);

/// A progress callback that redraws one line on stderr when it is a terminal, or with `always`
/// prints one line per check whatever stderr is (--progress: logs, wrappers); quiet otherwise.
/// Ctrl-C is not its business: main() installs io::installInterruptHandlers.
std::function<bool(const FlowProgress&)> terminalProgress(const std::string& label, bool always);

/// Registers --progress (terminalProgress's `always`) on `cmd`.
void addProgressFlag(CLI::App& cmd, bool& always);

/// Clears the progress line (if one was drawn).
void endProgressLine();

}  // namespace elastica::cli
