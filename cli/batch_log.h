// SPDX-License-Identifier: GPL-3.0-or-later
// What a batch tells: one JSON line per input in --log, a progress line on a terminal, and a table
// at the end.
#pragma once

#include "batch_inputs.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace elastica::cli {

enum class ItemStatus { Pending, Ok, Skipped, Failed, TimedOut, Interrupted };
const char* nameOf(ItemStatus s);

/// How one input went. `stop`, `energies` and `holes` come from the command's report (null without
/// one): fair's whole-mesh energies; fill's patch energies summed and its holes filled and skipped.
struct ItemOutcome {
  ItemStatus status = ItemStatus::Pending;
  double seconds = 0;
  nlohmann::json stop, energies, holes;
  std::string error;
};

/// The stop reason and energies of a `fair` or `fill` --report, as the log holds them.
void readReport(const nlohmann::json& report, ItemOutcome& outcome);

/// The --log file: truncated when opened, one line per input written (and flushed) as it ends.
class BatchLog {
 public:
  /// No file for an empty `path`. @throws IoError if it cannot be opened.
  explicit BatchLog(const std::string& path);
  void write(const BatchItem& item, const ItemOutcome& outcome);

 private:
  std::string path_;
  std::ofstream out_;
};

/// Counts of the outcomes so far, for the progress line and the last line.
struct BatchCounts {
  int total = 0, ok = 0, skipped = 0, failed = 0, interrupted = 0, running = 0;
  int done() const { return ok + skipped + failed; }
};

/// The line "batch: 12/45 done, 1 failed, 3 skipped, 2 running, ETA 1m05s" redrawn on stderr when it
/// is a terminal; silent otherwise.
class ProgressLine {
 public:
  ProgressLine();
  void draw(const BatchCounts& c);
  void clear();

 private:
  bool tty_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

/// The table of every input (status, seconds, stop, energy, error) and a line of totals, on `out`.
void printSummary(std::FILE* out, const std::vector<BatchItem>& items, const std::vector<ItemOutcome>& outcomes,
                  const BatchCounts& counts, double seconds, int jobs);

}  // namespace elastica::cli
