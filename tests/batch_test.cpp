// SPDX-License-Identifier: GPL-3.0-or-later
// `elastica batch` end to end through the real binary: its outputs are the single-file command's
// bytes, a bad input fails alone, an interrupted batch leaves only whole files and a second run
// finishes it, and shards partition the inputs.
#include "elastica_child.h"
#include "file_helpers.h"
#include "run_elastica.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace elastica {
using test::Child;
using test::quoted;
using test::readFile;
using test::runElastica;
using test::ScratchDir;
namespace fs = std::filesystem;

namespace {

// Small noisy icospheres in `folder`: m1.ply … mN.ply (level 2: 162 vertices, fairs in well under a second).
void writeSpheres(const std::string& folder, int n) {
  fs::create_directories(folder);
  for (int i = 1; i <= n; ++i)
    ASSERT_EQ(runElastica("generate icosphere --level 2 --noise 0.05 --seed " + std::to_string(i) + " -o " +
                          quoted(folder + "/m" + std::to_string(i) + ".ply"))
                  .exitCode,
              0);
}

// The --log file's lines, by input.
std::map<std::string, nlohmann::json> logByInput(const std::string& path) {
  std::map<std::string, nlohmann::json> byInput;
  std::istringstream in(readFile(path));
  for (std::string line; std::getline(in, line);) {
    const nlohmann::json j = nlohmann::json::parse(line);
    EXPECT_EQ(byInput.count(j["input"]), 0u) << "logged twice: " << j["input"];
    byInput[j["input"]] = j;
  }
  return byInput;
}

// Names in `dir` (not recursive), hidden ones included.
std::set<std::string> namesIn(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// What `elastica COMMAND INPUT -o OUT [options]` alone writes.
std::string singleFileOutput(const std::string& command, const std::string& input, const std::string& options,
                             const ScratchDir& dir) {
  const std::string out = dir.file("single-" + fs::path(input).stem().string() + ".ply");
  const test::CommandResult r = runElastica(command + " " + quoted(input) + " -o " + quoted(out) + " " + options);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return readFile(out);
}

bool waitForLines(const std::string& path, int lines, double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    const std::string text = readFile(path);
    if (std::count(text.begin(), text.end(), '\n') >= lines) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

}  // namespace

// Two good meshes and a file that is no PLY in one folder (a text file beside them is not an
// input): the good outputs are the single-file command's bytes (that one run on every thread, the
// batch's on one), the bad one is logged with the reader's error and written nowhere, and the exit
// status says something failed.
TEST(Batch, FolderWithABadFile) {
  ScratchDir dir("batch-bad");
  const std::string in = dir.file("in"), out = dir.file("out"), log = dir.file("log.jsonl");
  writeSpheres(in, 2);
  test::writeText(in + "/bad.ply", "not a mesh\n");
  test::writeText(in + "/notes.txt", "not an input\n");
  const test::CommandResult r = runElastica("batch fair -o " + quoted(out) + " -j 2 --max-steps 30 --log " + quoted(log) + " " + quoted(in));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("1 of 3 inputs failed"), std::string::npos) << r.output;

  const auto byInput = logByInput(log);
  ASSERT_EQ(byInput.size(), 3u) << readFile(log);
  const nlohmann::json& bad = byInput.at(in + "/bad.ply");
  EXPECT_EQ(bad["status"], "failed");
  EXPECT_NE(bad["error"].get<std::string>().find("malformed PLY"), std::string::npos) << bad;
  for (const char* m : {"m1", "m2"}) {
    const nlohmann::json& good = byInput.at(in + "/" + m + ".ply");
    EXPECT_EQ(good["status"], "ok") << good;
    EXPECT_EQ(good["output"], out + "/" + m + ".ply");
    EXPECT_LT(good["energies"]["after"].get<double>(), good["energies"]["before"].get<double>()) << good;
    EXPECT_EQ(readFile(out + "/" + m + ".ply"), singleFileOutput("fair", in + "/" + m + ".ply", "--max-steps 30", dir)) << m;
  }
  EXPECT_EQ(namesIn(out), (std::set<std::string>{".elastica-batch", "m1.ply", "m2.ply"}));
}

// SIGINT once the first output is logged (-j 1, so the next run has just started): the batch
// passes it on and dies of it, every file in the output folder is a whole output with the
// single-file bytes and no temporary is left; run again, it skips what was done and finishes the rest.
TEST(Batch, KillAndResume) {
  ScratchDir dir("batch-resume");
  const std::string in = dir.file("in"), out = dir.file("out"), log = dir.file("log.jsonl");
  writeSpheres(in, 4);
  {
    Child batch({"batch", "fair", "-o", out, "--log", log, in});
    ASSERT_TRUE(waitForLines(log, 1, 120)) << readFile(log);
    const int status = batch.interrupt(SIGINT);
    ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << status << "\n" << batch.output();
    EXPECT_EQ(WTERMSIG(status), SIGINT);
  }
  std::set<std::string> done;
  for (const std::string& name : namesIn(out)) {
    if (name == ".elastica-batch") continue;
    ASSERT_NE(name[0], '.') << "a temporary file was left: " << name;
    EXPECT_EQ(readFile(out + "/" + name), singleFileOutput("fair", in + "/" + name, "", dir)) << name;
    done.insert(name);
  }
  ASSERT_GE(done.size(), 1u);
  ASSERT_LT(done.size(), 4u) << "the interrupt came after the batch ended: nothing to resume";

  const test::CommandResult again = runElastica("batch fair -o " + quoted(out) + " --log " + quoted(log) + " " + quoted(in));
  EXPECT_EQ(again.exitCode, 0) << again.output;
  const auto byInput = logByInput(log);
  ASSERT_EQ(byInput.size(), 4u);
  for (int i = 1; i <= 4; ++i) {
    const std::string name = "m" + std::to_string(i) + ".ply";
    EXPECT_EQ(byInput.at(in + "/" + name)["status"], done.count(name) ? "skipped" : "ok") << name;
    EXPECT_EQ(readFile(out + "/" + name), singleFileOutput("fair", in + "/" + name, "", dir)) << name;
  }
  EXPECT_NE(again.output.find(std::to_string(done.size()) + " done before (skipped)"), std::string::npos) << again.output;
}

// A record holds the options and the input's bytes: other options or a changed input run again.
TEST(Batch, ChangedOptionsOrInputRunAgain) {
  ScratchDir dir("batch-record");
  const std::string in = dir.file("in"), out = dir.file("out"), log = dir.file("log.jsonl");
  writeSpheres(in, 2);
  const std::string batch = "batch curvature -o " + quoted(out) + " --log " + quoted(log) + " " + quoted(in);
  ASSERT_EQ(runElastica(batch).exitCode, 0);
  ASSERT_EQ(runElastica(batch).exitCode, 0);
  EXPECT_EQ(logByInput(log).at(in + "/m1.ply")["status"], "skipped");
  ASSERT_EQ(runElastica(batch + " --ascii").exitCode, 0);
  EXPECT_EQ(logByInput(log).at(in + "/m1.ply")["status"], "ok");
  EXPECT_EQ(readFile(out + "/m1.ply"), singleFileOutput("curvature", in + "/m1.ply", "--ascii", dir));
  ASSERT_EQ(runElastica("generate icosphere --level 2 --noise 0.05 --seed 9 -o " + quoted(in + "/m1.ply")).exitCode, 0);
  ASSERT_EQ(runElastica(batch + " --ascii").exitCode, 0);
  const auto byInput = logByInput(log);
  EXPECT_EQ(byInput.at(in + "/m1.ply")["status"], "ok");
  EXPECT_EQ(byInput.at(in + "/m2.ply")["status"], "skipped");
}

// Shards 1/3, 2/3 and 3/3 of seven inputs run each input exactly once between them; a Slurm array
// task (IDs 10…12) picks the same shard as --shard does.
TEST(Batch, ShardsPartitionTheInputs) {
  ScratchDir dir("batch-shards");
  const std::string in = dir.file("in"), out = dir.file("out");
  writeSpheres(in, 7);
  std::map<std::string, int> runs;
  std::vector<std::set<std::string>> shards(3);
  for (int s = 1; s <= 3; ++s) {
    const std::string log = dir.file("log" + std::to_string(s) + ".jsonl");
    const test::CommandResult r = runElastica("batch curvature -o " + quoted(out) + " --shard " + std::to_string(s) + "/3 --log " +
                                              quoted(log) + " " + quoted(in));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const auto& [input, line] : logByInput(log)) {
      EXPECT_EQ(line["status"], "ok");
      ++runs[input];
      shards[s - 1].insert(input);
    }
    EXPECT_GE(shards[s - 1].size(), 2u);
  }
  EXPECT_EQ(runs.size(), 7u);
  for (const auto& [input, n] : runs) EXPECT_EQ(n, 1) << input;

  const std::string log = dir.file("slurm.jsonl");
  const test::CommandResult r = test::runCommand("SLURM_ARRAY_TASK_ID=11 SLURM_ARRAY_TASK_MIN=10 SLURM_ARRAY_TASK_MAX=12 SLURM_ARRAY_TASK_COUNT=3 " +
                                                 std::string(ELASTICA_EXE) + " batch curvature -o " + quoted(dir.file("out2")) +
                                                 " --log " + quoted(log) + " " + quoted(in));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::set<std::string> slurm;
  for (const auto& entry : logByInput(log)) slurm.insert(entry.first);
  EXPECT_EQ(slurm, shards[1]);
  EXPECT_NE(r.output.find("shard 2/3 (SLURM_ARRAY_TASK_ID=11)"), std::string::npos) << r.output;
  // An array given as a list (1,3,7) says nothing of which shard a task is: refused.
  const test::CommandResult list = test::runCommand(
      "SLURM_ARRAY_TASK_ID=3 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=7 SLURM_ARRAY_TASK_COUNT=3 " + std::string(ELASTICA_EXE) +
      " batch curvature -o " + quoted(dir.file("out3")) + " " + quoted(in));
  EXPECT_EQ(list.exitCode, 2) << list.output;
  EXPECT_NE(list.output.find("pass --shard"), std::string::npos) << list.output;
}

// COMMAND's options are checked by COMMAND before any run; batch's own refuse what it sets itself.
TEST(Batch, BadCommandLinesStopBeforeAnyRun) {
  ScratchDir dir("batch-args");
  const std::string in = dir.file("in"), out = dir.file("out");
  writeSpheres(in, 1);
  for (const std::string& bad : {"fair --max-steps -1", "fair --no-such-option", "fair --report r.json", "subdivide",
                                 "fair --shard 4/3", "fair --format vrml"}) {
    const test::CommandResult r = runElastica("batch " + bad + " -o " + quoted(out) + " " + quoted(in));
    EXPECT_EQ(r.exitCode, 2) << bad << "\n" << r.output;
    EXPECT_FALSE(fs::exists(out + "/m1.ply")) << bad;
  }
  // Two inputs would write one output: refused, naming both.
  fs::create_directories(in + "/sub");
  fs::copy_file(in + "/m1.ply", in + "/sub/m1.ply");
  const test::CommandResult r = runElastica("batch curvature -o " + quoted(out) + " " + quoted(in));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("would both write"), std::string::npos) << r.output;
}

}  // namespace elastica
