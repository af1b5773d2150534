#include "flow_report.h"

#include <elastica/app/choices.h>
#include <elastica/errors.h>
#include <elastica/io/atomic_file.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>

namespace elastica::cli {
namespace {

bool gLineDrawn = false;

}  // namespace

nlohmann::json toJson(const FlowReport& r) {
  nlohmann::json j;
  j["energy_initial"] = r.energyInitial;
  j["energy_final"] = r.energyFinal;
  j["steps"] = r.steps;
  j["rejected_steps"] = r.rejectedSteps;
  j["seconds"] = r.seconds;
  j["stop"] = app::nameOf(r.stop);
  j["min_lambda"] = r.minLambda;
  j["stages"] = nlohmann::json::array();
  for (const FlowStage& s : r.stages)
    j["stages"].push_back({{"level", s.level}, {"vertices", s.vertices}, {"faces", s.faces}, {"steps", s.steps},
                           {"energy", s.energy}, {"seconds", s.seconds}});
  j["energy_history"] = nlohmann::json::array();
  for (const EnergySample& h : r.history)
    j["energy_history"].push_back({{"step", h.step}, {"time", h.time}, {"seconds", h.seconds}, {"energy", h.energy}});
  return j;
}

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
