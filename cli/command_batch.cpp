// SPDX-License-Identifier: GPL-3.0-or-later
// `elastica batch COMMAND -o DIR [options of COMMAND] INPUT...`: run fair, fill or curvature over
// many meshes. Each input runs as `elastica COMMAND INPUT -o DIR/<stem>.<format> [options]`, a child
// process of this same program on one thread, so its output has the single-file command's bytes by
// construction and batch never needs to know COMMAND's options. A record beside each output lets a
// second run skip what is done; --shard (or a Slurm array task) picks a fixed part of the inputs.
#include "batch_arguments.h"
#include "batch_inputs.h"
#include "batch_log.h"
#include "batch_record.h"
#include "batch_runner.h"
#include "commands.h"

#include <elastica/errors.h>
#include <elastica/io/atomic_file.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace elastica::cli {
namespace fs = std::filesystem;

namespace {

struct BatchArgs {
  std::string outputDir, shard, format = "ply", log;
  int jobs = 1;
  double maxSeconds = 0;
};

// The commands a batch runs, by name (their options come from their own definitions).
const std::map<std::string, void (*)(CLI::App&)>& batchCommands() {
  static const std::map<std::string, void (*)(CLI::App&)> commands{
      {"curvature", addCurvatureCommand}, {"fair", addFairCommand}, {"fill", addFillCommand}};
  return commands;
}

void addBatchOptions(CLI::App& cmd, BatchArgs& a) {
  cmd.add_option("-o,--output", a.outputDir, "output folder (made if missing): one DIR/<stem>.<format> per input");
  cmd.add_option("-j,--jobs", a.jobs, "inputs run at once, each on one thread")->check(CLI::PositiveNumber);
  cmd.add_option("--shard", a.shard,
                 "run part I of N (1-based; e.g. 2/4) of the sorted inputs; default from a Slurm array task "
                 "(SLURM_ARRAY_TASK_ID, _COUNT, _MIN, _STEP), else all");
  cmd.add_option("--max-seconds", a.maxSeconds,
                 "time limit per input: passed on as COMMAND's own --max-seconds (fair, fill: the flow stops and the "
                 "mesh is written), the run killed at twice it; a COMMAND without one is killed at it (the input fails)")
      ->check(CLI::PositiveNumber);
  cmd.add_option("--format", a.format, "output format: ply, off, obj or stl (default ply)")
      ->check(CLI::IsMember({"ply", "off", "obj", "stl"}));
  cmd.add_option("--log", a.log, "write one JSON line per input (input, output, status, stop, seconds, energies, error)");
}

void parseReversed(CLI::App& app, std::vector<std::string> words) {
  std::reverse(words.begin(), words.end());  // CLI11 takes a vector last word first
  app.parse(words);
}

// COMMAND's options checked once by COMMAND's own parser (with a stand-in input and output), so
// a wrong one stops the batch before any run rather than failing every input.
void checkForwardedOptions(CLI::App& probe, const std::string& command, const std::vector<std::string>& options,
                           const std::string& format) {
  // The top level's parse-complete callback runs after COMMAND's checks and before its work: stop there.
  struct Checked {};
  probe.parse_complete_callback([] { throw Checked(); });
  std::vector<std::string> words{command, "-o", "batch-check." + format};
  words.insert(words.end(), options.begin(), options.end());
  words.insert(words.end(), {"--", "batch-check.ply"});
  try {
    parseReversed(probe, words);
  } catch (const Checked&) {
    return;
  }
  throw std::logic_error("batch: the check of COMMAND's options ran COMMAND");
}

// The program's identity for the records: its version and the digest of its executable.
std::string programKey() { return std::string("elastica ") + ELASTICA_VERSION + " " + fileDigest("/proc/self/exe"); }

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The error a failed run printed: its last "elastica: " line without the prefix, else its last line.
std::string errorOf(const std::string& stderrText) {
  std::istringstream in(stderrText);
  std::string line, last, said;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    last = line;
    if (line.rfind("elastica: ", 0) == 0) said = line;
  }
  std::string e = said.empty() ? last : said;
  for (const char* prefix : {"elastica: error: ", "elastica: "})
    if (e.rfind(prefix, 0) == 0) return e.substr(std::strlen(prefix));
  return e;
}

struct Plan {
  std::string command;
  RunKey key;
  bool wantsReport = false;  // COMMAND has --report: the log takes its stop and energies from it
  double killAfter = 0;      // seconds after which a run is killed (0: never)
  std::vector<BatchItem> items;
  Shard shard;
  int allInputs = 0;
};

Plan makePlan(CLI::App& cmd, BatchArgs& a) {
  const std::vector<std::string> words = cmd.remaining();
  if (words.empty()) throw CLI::RequiredError("batch: COMMAND (fair, fill or curvature)");
  Plan plan;
  plan.command = words[0];
  const auto found = batchCommands().find(plan.command);
  if (found == batchCommands().end())
    throw CLI::ValidationError("batch", "'" + plan.command + "' is not a command batch runs (fair, fill or curvature)");
  CLI::App probe, own;
  found->second(probe);
  addBatchOptions(own, a);
  const BatchWords split = splitBatchWords({words.begin() + 1, words.end()}, own, *probe.get_subcommand(plan.command));
  parseReversed(own, split.batchOptions);
  if (a.outputDir.empty()) throw CLI::RequiredError("batch: -o DIR");
  if (split.inputs.empty()) throw CLI::RequiredError("batch: INPUT (files or folders)");
  plan.wantsReport = probe.get_subcommand(plan.command)->get_option_no_throw("--report") != nullptr;
  checkForwardedOptions(probe, plan.command, split.commandOptions, a.format);
  plan.shard = a.shard.empty() ? shardFromEnvironment() : parseShard(a.shard);
  plan.key = {programKey(), plan.command, split.commandOptions};
  // A command with its own time limit stops its flow there and writes what it has; the kill is the backstop.
  const bool ownLimit = probe.get_subcommand(plan.command)->get_option_no_throw("--max-seconds") != nullptr;
  if (ownLimit && a.maxSeconds > 0) plan.key.options.insert(plan.key.options.end(), {"--max-seconds", CLI::detail::to_string(a.maxSeconds)});
  plan.killAfter = ownLimit ? 2 * a.maxSeconds : a.maxSeconds;

  std::error_code ec;
  fs::create_directories(a.outputDir, ec);
  if (!fs::is_directory(a.outputDir)) throw IoError(a.outputDir + ": cannot make the output folder");
  io::checkOutputPath((fs::path(a.outputDir) / "x").string());  // writable
  const std::vector<std::string> inputs = findMeshInputs(split.inputs, a.outputDir);
  if (inputs.empty()) throw IoError("no .ply, .off, .obj or .stl file in the inputs given");
  const std::vector<BatchItem> all = assignOutputs(inputs, a.outputDir, a.format);
  plan.allInputs = static_cast<int>(all.size());
  plan.items = itemsOfShard(all, plan.shard);
  return plan;
}

JobLaunch launchOf(const Plan& plan, const BatchItem& item, const std::string& scratch, int job) {
  const std::string base = (fs::path(scratch) / std::to_string(job)).string();
  JobLaunch l;
  l.program = "/proc/self/exe";
  l.argv = {"elastica", plan.command, "-o", item.output};
  l.argv.insert(l.argv.end(), plan.key.options.begin(), plan.key.options.end());
  if (plan.wantsReport) l.argv.insert(l.argv.end(), {"--report", base + ".json"});
  l.argv.insert(l.argv.end(), {"--", item.input});
  l.environment = {"OMP_NUM_THREADS=1"};
  l.stdoutPath = base + ".out";
  l.stderrPath = base + ".err";
  return l;
}

ItemOutcome outcomeOf(const JobEnd& end, const std::string& scratch, int job, const Plan& plan) {
  const std::string base = (fs::path(scratch) / std::to_string(job)).string();
  ItemOutcome o;
  o.seconds = end.seconds;
  std::ifstream report(base + ".json");
  if (report) readReport(nlohmann::json::parse(report, nullptr, false), o);
  if (end.exitCode == 0) o.status = ItemStatus::Ok;
  else if (end.timedOut) {
    o.status = ItemStatus::TimedOut;
    o.error = "killed after " + CLI::detail::to_string(plan.killAfter) + " s (--max-seconds)";
  } else if (end.stopping && end.signal) {
    o.status = ItemStatus::Interrupted;
    o.error = std::string("interrupted by SIG") + sigabbrev_np(end.signal);
  } else {
    o.status = ItemStatus::Failed;
    o.error = errorOf(readText(base + ".err"));
    if (end.signal) o.error = std::string("killed by SIG") + sigabbrev_np(end.signal) + (o.error.empty() ? "" : ": " + o.error);
    if (o.error.empty()) o.error = "exit status " + std::to_string(end.exitCode);
  }
  for (const char* ext : {".json", ".out", ".err"}) std::remove((base + ext).c_str());
  return o;
}

void runBatch(CLI::App& cmd, BatchArgs& a) {
  const auto start = std::chrono::steady_clock::now();
  const Plan plan = makePlan(cmd, a);
  const int n = static_cast<int>(plan.items.size());
  std::vector<ItemOutcome> outcomes(plan.items.size());
  std::vector<std::string> digests(plan.items.size());
  std::vector<int> todo;  // indices into plan.items still to run
  BatchLog log(a.log);
  BatchCounts counts;
  counts.total = n;
  for (int i = 0; i < n; ++i) {
    digests[i] = fileDigest(plan.items[i].input);
    if (isDone(plan.items[i], plan.key, digests[i])) {
      outcomes[i].status = ItemStatus::Skipped;
      ++counts.skipped;
      log.write(plan.items[i], outcomes[i]);
    } else {
      todo.push_back(i);
    }
  }
  std::printf("batch %s: %d input%s", plan.command.c_str(), plan.allInputs, plan.allInputs == 1 ? "" : "s");
  if (plan.shard.count > 1)
    std::printf(", shard %d/%d%s: %d of them", plan.shard.index, plan.shard.count,
                plan.shard.from.empty() ? "" : (" (" + plan.shard.from + ")").c_str(), n);
  std::printf("; %d done before (skipped), %zu to run, -j %d, into %s\n", counts.skipped, todo.size(), a.jobs,
              a.outputDir.c_str());
  std::fflush(stdout);

  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = (fs::path(tmp && *tmp ? tmp : "/tmp") / "elastica-batch.XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw IoError("cannot make a scratch folder for the batch's runs");
  const std::string scratch = pattern;
  ProgressLine progress;
  int stoppedBy = 0;
  try {
    stoppedBy = runJobs(
        static_cast<int>(todo.size()), {a.jobs, plan.killAfter},
        [&](int j) {
          ++counts.running;
          return launchOf(plan, plan.items[todo[j]], scratch, j);
        },
        [&](int j, const JobEnd& end) {
          const int i = todo[j];
          --counts.running;
          outcomes[i] = outcomeOf(end, scratch, j, plan);
          if (outcomes[i].status == ItemStatus::Ok) writeRecord(plan.items[i], plan.key, digests[i]);
          if (outcomes[i].status == ItemStatus::Ok) ++counts.ok;
          else if (outcomes[i].status == ItemStatus::Interrupted) ++counts.interrupted;
          else ++counts.failed;
          log.write(plan.items[i], outcomes[i]);
          progress.draw(counts);
        },
        [&] { progress.draw(counts); });
  } catch (...) {
    progress.clear();
    fs::remove_all(scratch);
    throw;
  }
  progress.clear();
  fs::remove_all(scratch);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  printSummary(stdout, plan.items, outcomes, counts, seconds, a.jobs);
  if (!a.log.empty()) std::printf("wrote %s\n", a.log.c_str());
  std::fflush(stdout);
  if (stoppedBy) {
    std::raise(stoppedBy);  // main's handler says so and dies of it (130 for Ctrl-C)
    throw std::runtime_error("interrupted");
  }
  if (counts.failed > 0)
    throw std::runtime_error(std::to_string(counts.failed) + " of " + std::to_string(n) + " input" + (n == 1 ? "" : "s") +
                             " failed (see the table" + (a.log.empty() ? "" : " and " + a.log) + ")");
}

}  // namespace

void addBatchCommand(CLI::App& app) {
  auto args = std::make_shared<BatchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "batch",
      "Run fair, fill or curvature over many meshes: elastica batch COMMAND -o DIR [options of COMMAND] INPUT...\n"
      "INPUT: files, or folders searched for .ply/.off/.obj/.stl. Each input runs as\n"
      "'elastica COMMAND INPUT -o DIR/<stem>.<format> [options]' on one thread (the same bytes); an output whose\n"
      "record (input bytes, command, options, program) matches is skipped, so a stopped batch resumes.\n"
      "Exit status 1 if any input failed; one bad input never stops the rest.");
  cmd->prefix_command();  // COMMAND and all after it are sorted by batch itself (batch_arguments.h)
  addBatchOptions(*cmd, *args);
  cmd->callback([cmd, args] { runBatch(*cmd, *args); });
}

}  // namespace elastica::cli
