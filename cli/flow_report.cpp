// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow_report.h"

#include <elastica/errors.h>
#include <elastica/io/atomic_file.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>

namespace elastica::cli {
namespace {

bool gLineDrawn = false;

}  // namespace

void writeJson(const std::string& path, const nlohmann::json& j) {
  io::writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << j.dump(2) << "\n";
    if (!out) throw IoError(path + ": cannot write the report");
  });
}

void writeReport(const std::string& path, nlohmann::json j, const std::string& input, const std::string& output) {
  j["input"]["file"] = input;
  j["output"]["file"] = output;
  writeJson(path, j);
  std::printf("wrote %s\n", path.c_str());
}

std::function<bool(const FlowProgress&)> terminalProgress(const std::string& label, bool always) {
  const bool tty = isatty(STDERR_FILENO);
  return [tty, always, label](const FlowProgress& p) {
    if (tty || always) {
      // The energy of the mesh the flow works on (refined or remeshed, or a region with its fixed
      // rings): it may differ from the whole mesh's the summary states. The paper's lambda only
      // where it applies.
      char lambda[48] = "";
      if (p.lambda < 1) std::snprintf(lambda, sizeof lambda, "  paper's lambda %.3g", p.lambda);
      std::fprintf(stderr, "%s%s: level %d  step %lld  flow energy %.6g%s  %.1f s%s", tty ? "\r" : "", label.c_str(),
                   p.level, p.step, p.energy, lambda, p.seconds, tty ? "   " : "\n");
      std::fflush(stderr);
      gLineDrawn = tty;
    }
    return true;
  };
}

void addProgressFlag(CLI::App& cmd, bool& always) {
  cmd.add_flag("--progress", always, "print progress on stderr, one line per check, even when it is not a terminal");
}

void endProgressLine() {
  if (gLineDrawn) std::fprintf(stderr, "\n");
  gLineDrawn = false;
}

}  // namespace elastica::cli
