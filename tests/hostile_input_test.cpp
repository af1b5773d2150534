// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile inputs through the real `elastica` binary: every file listed in tests/hostile/cases.txt
// and every bad path below must give one clear error naming the file, an exit code in 1..127 and
// no file written (no output, no temporary left beside it) -- or, for the repairable ones, exit 0
// with a note saying what was repaired. The outcomes are also written as a Markdown table to
// <build>/hostile_inputs-<test>.md (docs/robustness.md's table is a copy of them).
#include "file_helpers.h"
#include "run_elastica.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

namespace elastica {
namespace fs = std::filesystem;
using test::CommandResult;
using test::runElastica;
using test::ScratchDir;

namespace {

struct Case {
  std::string file;
  int exitCode;
  std::string expected, what;
};

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<Case> readCases() {
  std::ifstream in(std::string(ELASTICA_HOSTILE_DIR) + "/cases.txt");
  std::vector<Case> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    size_t start = 0, bar;
    while ((bar = line.find(" | ", start)) != std::string::npos) f.push_back(trim(line.substr(start, bar - start))), start = bar + 3;
    f.push_back(trim(line.substr(start)));
    if (f.size() != 4) throw std::runtime_error("cases.txt: bad line: " + line);
    cases.push_back({f[0], std::stoi(f[1]), f[2], f[3]});
  }
  return cases;
}

std::set<std::string> filesIn(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// The last line of the output (the error, after any notes), without the newline.
std::string lastLine(const std::string& out) {
  std::string s = out;
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s.substr(s.rfind('\n') == std::string::npos ? 0 : s.rfind('\n') + 1);
}

class Table {
 public:
  /// One row; `scratch` (the test's temporary directory) is cut out of the message.
  void add(const std::string& input, const std::string& command, const CommandResult& r, const std::string& scratch) {
    std::string msg = r.exitCode == 0 ? "" : lastLine(r.output);
    if (r.exitCode == 0)
      for (size_t a = 0, b; a < r.output.size(); a = b + 1) {
        b = r.output.find('\n', a);
        if (b == std::string::npos) b = r.output.size();
        const std::string l = r.output.substr(a, b - a);
        if (l.rfind("note:", 0) == 0 || l.rfind("degenerate", 0) == 0) msg += (msg.empty() ? "" : " / ") + l;
      }
    for (size_t at; (at = msg.find(scratch + "/")) != std::string::npos;) msg.erase(at, scratch.size() + 1);
    for (char& c : msg)
      if (c == '|') c = '/';
    rows_ += "| " + input + " | `" + command + "` | " + std::to_string(r.exitCode) + " | " + msg + " |\n";
  }
  // One file per test (ctest runs each in its own process): hostile_inputs-<test>.md.
  ~Table() {
    if (rows_.empty()) return;
    std::ofstream(std::string(ELASTICA_BUILD_DIR) + "/hostile_inputs-" + test_ + ".md")
        << "| input | command | exit | message |\n|---|---|---|---|\n" << rows_;
  }

 private:
  std::string rows_;
  std::string test_ = ::testing::UnitTest::GetInstance()->current_test_info()->name();
};

Table& table() {
  static Table t;
  return t;
}

// Runs `command` in `dir` (holding only the inputs) and checks a refusal: exit 1..127, the
// message names `named`, holds `expected`, and nothing new appeared in `dir`.
void expectRefused(const ScratchDir& dir, const std::string& label, const std::string& command,
                   const std::string& named, const std::string& expected) {
  const std::set<std::string> before = filesIn(dir.path());
  const CommandResult r = runElastica(command);
  table().add(label, command.substr(0, command.find(' ')), r, dir.path().string());
  EXPECT_GE(r.exitCode, 1) << command << "\n" << r.output;
  EXPECT_LE(r.exitCode, 127) << command << "\n" << r.output;
  const std::string err = lastLine(r.output);
  EXPECT_EQ(err.rfind("elastica: error: ", 0), 0u) << err;
  EXPECT_NE(err.find(named), std::string::npos) << "the message does not name " << named << ": " << err;
  EXPECT_NE(err.find(expected), std::string::npos) << "expected '" << expected << "' in: " << err;
  EXPECT_EQ(filesIn(dir.path()), before) << command << " left a file behind";
}

}  // namespace

TEST(HostileInput, EveryListedFileIsRefusedOrRepairedWithAClearMessage) {
  const std::vector<Case> cases = readCases();
  int refused = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file + ": " + c.what);
    ScratchDir dir("hostile");
    const std::string in = dir.file(c.file);
    fs::copy_file(std::string(ELASTICA_HOSTILE_DIR) + "/" + c.file, in);
    const std::string out = dir.file("out.ply");
    if (c.exitCode == 0) {
      const CommandResult r = runElastica("curvature " + in + " -o " + out);
      table().add(c.file, "curvature", r, dir.path().string());
      EXPECT_EQ(r.exitCode, 0) << r.output;
      EXPECT_NE(r.output.find(c.expected), std::string::npos) << r.output;
      EXPECT_TRUE(fs::exists(out));
      continue;
    }
    // The readers are shared: curvature and fair must both refuse, with the same message.
    expectRefused(dir, c.file, "curvature " + in + " -o " + out, in, c.expected);
    expectRefused(dir, c.file, "fair " + in + " -o " + out + " --max-steps 10", in, c.expected);
    ++refused;
  }
  EXPECT_GE(refused, 25);
}

TEST(HostileInput, BadPathsAreRefusedBeforeAnyWork) {
  ScratchDir dir("hostile-paths");
  const std::string good = std::string(ELASTICA_HOSTILE_DIR) + "/repair_duplicate_face.off";
  fs::copy_file(good, dir.file("in.off"));
  const std::string in = dir.file("in.off");
  expectRefused(dir, "missing input", "curvature " + dir.file("missing.ply") + " -o " + dir.file("o.ply"), "missing.ply",
                "no such file");
  fs::create_directory(dir.file("folder.ply"));
  expectRefused(dir, "input is a directory", "fair " + dir.file("folder.ply") + " -o " + dir.file("o.ply"), "folder.ply",
                "is a directory");
  ASSERT_EQ(mkfifo(dir.file("fifo.ply").c_str(), 0600), 0);
  expectRefused(dir, "input is a FIFO", "curvature " + dir.file("fifo.ply") + " -o " + dir.file("o.ply"), "fifo.ply",
                "not a regular file");
  fs::create_symlink(dir.file("nowhere.ply"), dir.file("dangling.ply"));
  expectRefused(dir, "dangling symbolic link", "curvature " + dir.file("dangling.ply") + " -o " + dir.file("o.ply"),
                "dangling.ply", "no such file");
  expectRefused(dir, "output directory missing", "curvature " + in + " -o " + dir.file("no/such/dir/o.ply"), "o.ply",
                "does not exist");
  expectRefused(dir, "output is a directory", "fair " + in + " -o " + dir.file("folder.ply"), "folder.ply",
                "is a directory, not an output file");
  expectRefused(dir, "output equals input", "fair " + in + " -o " + in, in, "overwrite the input");
  expectRefused(dir, "output equals input by another name", "curvature " + in + " -o " + dir.path().string() + "/./in.off",
                "in.off", "overwrite the input");
  expectRefused(dir, "report equals input", "fair " + in + " -o " + dir.file("o.ply") + " --report " + in, in,
                "overwrite the input");
  expectRefused(dir, "generate into a missing directory", "generate icosphere -o " + dir.file("none/s.ply"), "s.ply",
                "does not exist");
  // A directory nobody can create files in, even root: /proc.
  expectRefused(dir, "output directory not writable (/proc)", "curvature " + in + " -o /proc/elastica-out.ply",
                "/proc/elastica-out.ply", "cannot create a temporary file");
  if (geteuid() != 0) {  // root reads anything: the permission case needs an ordinary user
    fs::copy_file(good, dir.file("locked.off"));
    fs::permissions(dir.file("locked.off"), fs::perms::none);
    expectRefused(dir, "unreadable input", "curvature " + dir.file("locked.off") + " -o " + dir.file("o.ply"),
                  "locked.off", "cannot open for reading");
    fs::permissions(dir.file("locked.off"), fs::perms::owner_all);
  }
}

// Inputs the reader accepts but the flow cannot work on.
TEST(HostileInput, FairRefusesWhatTheFlowCannotMove) {
  ScratchDir dir("hostile-fair");
  const std::string h = ELASTICA_HOSTILE_DIR;
  fs::copy_file(h + "/repair_unreferenced_vertex.off", dir.file("triangle.off"));
  expectRefused(dir, "a single triangle (nothing can move)", "fair " + dir.file("triangle.off") + " -o " + dir.file("o.ply"),
                "triangle.off", "no vertex can move");
  expectRefused(dir, "--selected without selection flags",
                "fair " + dir.file("triangle.off") + " -o " + dir.file("o.ply") + " --selected", "triangle.off",
                "no face selection");
}

}  // namespace elastica
