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

std::function<bool(const FlowProgress&)> terminalProgress(const std::string& label, bool always) {
  const bool tty = isatty(STDERR_FILENO);
  return [tty, always, label](const FlowProgress& p) {
    if (tty || always) {
      std::fprintf(stderr, "%s%s: level %d  step %lld  E %.6g  lambda %.3g  %.1f s%s", tty ? "\r" : "", label.c_str(),
                   p.level, p.step, p.energy, p.lambda, p.seconds, tty ? "   " : "\n");
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
