// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch_log.h"

#include <elastica/errors.h>

#include <unistd.h>

#include <algorithm>

namespace elastica::cli {

const char* nameOf(ItemStatus s) {
  switch (s) {
    case ItemStatus::Pending: return "not run";
    case ItemStatus::Ok: return "ok";
    case ItemStatus::Skipped: return "skipped";
    case ItemStatus::Failed: return "failed";
    case ItemStatus::TimedOut: return "timeout";
    case ItemStatus::Interrupted: return "interrupted";
  }
  return "?";
}

void readReport(const nlohmann::json& r, ItemOutcome& o) {
  if (!r.is_object()) return;
  if (r.contains("stop")) o.stop = r["stop"];
  if (r.contains("mesh_energy_before") && r.contains("mesh_energy_after"))
    o.energies = {{"before", r["mesh_energy_before"]}, {"after", r["mesh_energy_after"]}};
  else if (r.contains("energy_initial") && r.contains("energy_final"))  // a fair that diverged
    o.energies = {{"before", r["energy_initial"]}, {"after", r["energy_final"]}};
  if (r.contains("holes") && r["holes"].is_array()) {  // fill: the patches' energies summed, the stops as words
    double before = 0, after = 0;
    std::string stops;
    for (const nlohmann::json& h : r["holes"]) {
      before += h.value("energy_before", 0.0);
      after += h.value("energy_after", 0.0);
      const std::string stop = h.value("stop", std::string());
      if (!stop.empty() && (stops + ",").find(stop + ",") == std::string::npos) stops += (stops.empty() ? "" : ",") + stop;
    }
    o.stop = stops;
    o.energies = {{"before", before}, {"after", after}};
    o.holes = {{"filled", r.value("filled", 0)}, {"skipped", r.value("skipped", 0)}};
  }
}

BatchLog::BatchLog(const std::string& path) : path_(path) {
  if (path.empty()) return;
  out_.open(path, std::ios::trunc);
  if (!out_) throw IoError(path + ": cannot write the batch log");
}

void BatchLog::write(const BatchItem& item, const ItemOutcome& o) {
  if (path_.empty()) return;
  nlohmann::json j{{"input", item.input}, {"output", item.output}, {"status", nameOf(o.status)},
                   {"stop", o.stop},      {"seconds", o.seconds},   {"energies", o.energies}};
  j["error"] = o.error.empty() ? nlohmann::json() : nlohmann::json(o.error);
  if (!o.holes.is_null()) j["holes"] = o.holes;
  out_ << j.dump() << "\n" << std::flush;
  if (!out_) throw IoError(path_ + ": cannot write the batch log");
}

ProgressLine::ProgressLine() : tty_(isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

void ProgressLine::draw(const BatchCounts& c) {
  if (!tty_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const int ran = c.ok + c.failed, left = c.total - c.done();
  std::string eta = "ETA --";
  if (ran > 0) {  // the wall time per finished run so far, over what is left
    const int s = static_cast<int>(elapsed / ran * left + 0.5);
    eta = "ETA " + (s >= 60 ? std::to_string(s / 60) + "m" : std::string()) + std::to_string(s % 60) + "s";
  }
  std::fprintf(stderr, "\rbatch: %d/%d done, %d failed, %d skipped, %d running, %s   ", c.done(), c.total, c.failed,
               c.skipped, c.running, eta.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::clear() {
  if (drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

namespace {

std::string energyText(const nlohmann::json& e) {
  char buf[64];
  if (e.is_object() && e["before"].is_number() && e["after"].is_number()) {
    std::snprintf(buf, sizeof buf, "%.6g -> %.6g", e["before"].get<double>(), e["after"].get<double>());
    return buf;
  }
  return "";
}

std::string stopText(const nlohmann::json& s) {
  if (s.is_string()) return s.get<std::string>();
  return "";
}

}  // namespace

void printSummary(std::FILE* out, const std::vector<BatchItem>& items, const std::vector<ItemOutcome>& outcomes,
                  const BatchCounts& c, double seconds, int jobs) {
  std::size_t width = 5;
  for (const BatchItem& it : items) width = std::max(width, it.input.size());
  const int w = static_cast<int>(width);
  std::fprintf(out, "%-*s  %-11s %8s  %-12s %s\n", w, "input", "status", "seconds", "stop", "energy / error");
  for (std::size_t i = 0; i < items.size(); ++i) {
    const ItemOutcome& o = outcomes[i];
    const std::string last = o.error.empty() ? energyText(o.energies) : o.error;
    std::fprintf(out, "%-*s  %-11s %8.2f  %-12s %s\n", w, items[i].input.c_str(), nameOf(o.status), o.seconds,
                 stopText(o.stop).c_str(), last.c_str());
  }
  const int notRun = c.total - c.done() - c.interrupted;
  std::string rest;
  if (c.interrupted) rest += ", " + std::to_string(c.interrupted) + " interrupted";
  if (notRun) rest += ", " + std::to_string(notRun) + " not run";
  std::fprintf(out, "%d input%s: %d ok, %d skipped (done before), %d failed%s; %.2f s with -j %d\n", c.total,
               c.total == 1 ? "" : "s", c.ok, c.skipped, c.failed, rest.c_str(), seconds, jobs);
}

}  // namespace elastica::cli
