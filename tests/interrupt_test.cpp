// SPDX-License-Identifier: GPL-3.0-or-later
// Ctrl-C and kill: an existing destination is never touched and no temporary file is left. The
// real `elastica` is interrupted in the middle of a flow (after its first --progress line, so
// the signal always arrives while it works); a forked writer is interrupted while its temporary
// file exists (it raises the signal itself, so the timing is fixed too).
#include "elastica_child.h"
#include "file_helpers.h"
#include "run_elastica.h"

#include <elastica/io/atomic_file.h>

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace elastica {
using test::Child;
using test::readFile;
using test::ScratchDir;

namespace {

std::set<std::string> filesIn(const ScratchDir& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) names.insert(e.path().filename().string());
  return names;
}

const char* kPrecious = "an earlier result that must survive\n";

struct Case {
  const char* name;
  int signal;
};
void PrintTo(const Case& c, std::ostream* os) { *os << "SIG" << c.name; }

class Interrupt : public testing::TestWithParam<Case> {};

}  // namespace

// `fair` with no step or energy limit would run for hours: interrupted after its first progress
// line, it dies of the signal, the existing output is byte for byte what it was, and nothing
// else is left in the directory.
TEST_P(Interrupt, FairLeavesTheDestinationUntouched) {
  const int sig = GetParam().signal;
  ScratchDir dir(std::string("interrupt-fair-") + GetParam().name);
  ASSERT_EQ(test::runElastica("generate icosphere --level 3 --noise 0.05 --seed 7 -o " + dir.file("n.ply")).exitCode, 0);
  test::writeText(dir.file("out.ply"), kPrecious);
  Child child({"fair", dir.file("n.ply"), "-o", dir.file("out.ply"), "--report", dir.file("r.json"), "--progress",
               "--max-steps", "1000000000", "--energy-tol", "0", "--feature-size", "0"});
  ASSERT_TRUE(child.waitFor("fair: level 0  step", 60)) << child.output();
  const int status = child.interrupt(sig);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << status << "\n" << child.output();
  EXPECT_EQ(WTERMSIG(status), sig);
  EXPECT_NE(child.output().find(std::string("elastica: interrupted by SIG") + GetParam().name), std::string::npos)
      << child.output();
  EXPECT_EQ(readFile(dir.file("out.ply")), kPrecious);
  EXPECT_EQ(filesIn(dir), (std::set<std::string>{"n.ply", "out.ply"}));
}

// The same for `fill` on the bunny's flank hole, with the explicit scheme and no energy plateau.
TEST_P(Interrupt, FillLeavesTheDestinationUntouched) {
  const int sig = GetParam().signal;
  ScratchDir dir(std::string("interrupt-fill-") + GetParam().name);
  test::writeText(dir.file("out.ply"), kPrecious);
  Child child({"fill", ELASTICA_DATA_DIR "/bunny_flank_hole.ply", "-o", dir.file("out.ply"), "--progress", "--scheme",
               "explicit", "--max-steps", "1000000000", "--energy-tol", "0"});
  ASSERT_TRUE(child.waitFor("fill: level 0  step", 120)) << child.output();
  const int status = child.interrupt(sig);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << status << "\n" << child.output();
  EXPECT_EQ(WTERMSIG(status), sig);
  EXPECT_EQ(readFile(dir.file("out.ply")), kPrecious);
  EXPECT_EQ(filesIn(dir), (std::set<std::string>{"out.ply"}));
}

INSTANTIATE_TEST_SUITE_P(Signals, Interrupt, testing::Values(Case{"INT", SIGINT}, Case{"TERM", SIGTERM}),
                         [](const testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// The signal arrives while the temporary file exists and holds half an output: the handler
// deletes it, the destination keeps its old content, and the process dies of the signal.
TEST(InterruptWhileWriting, TemporaryRemovedDestinationUntouched) {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    ScratchDir dir("interrupt-write");
    const std::string dest = dir.file("out.ply");
    test::writeText(dest, kPrecious);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      io::installInterruptHandlers("writer");
      io::writeAtomically(dest, [sig](const std::string& tmp) {
        test::writeText(tmp, "half an outp");
        if (!std::filesystem::exists(tmp)) _exit(3);
        std::raise(sig);
      });
      _exit(4);  // not reached: the handler does not return
    }
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status)) << "signal " << sig << ": exit status " << status;
    EXPECT_EQ(WTERMSIG(status), sig);
    EXPECT_EQ(readFile(dest), kPrecious);
    EXPECT_EQ(filesIn(dir), (std::set<std::string>{"out.ply"})) << "signal " << sig;
  }
}

// A signal ignored before the handlers are installed (nohup, `cmd &` in a script) stays ignored.
TEST(InterruptWhileWriting, IgnoredSignalStaysIgnored) {
  ScratchDir dir("interrupt-ignored");
  const std::string dest = dir.file("out.ply");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGHUP, SIG_IGN);
    io::installInterruptHandlers("writer");
    io::writeAtomically(dest, [](const std::string& tmp) {
      test::writeText(tmp, "complete");
      std::raise(SIGHUP);
    });
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "exit status " << status;
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(readFile(dest), "complete");
  EXPECT_EQ(filesIn(dir), (std::set<std::string>{"out.ply"}));
}

}  // namespace elastica
