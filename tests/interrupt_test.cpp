// Ctrl-C and kill: an existing destination is never touched and no temporary file is left. The
// real `elastica` is interrupted in the middle of a flow (after its first --progress line, so
// the signal always arrives while it works); a forked writer is interrupted while its temporary
// file exists (it raises the signal itself, so the timing is fixed too).
#include "file_helpers.h"
#include "run_elastica.h"

#include <elastica/io/atomic_file.h>

#include <gtest/gtest.h>

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

extern char** environ;

namespace elastica {
using test::ScratchDir;

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::set<std::string> filesIn(const ScratchDir& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) names.insert(e.path().filename().string());
  return names;
}

// `elastica ARGS...` with stdout and stderr on a pipe.
class Child {
 public:
  explicit Child(const std::vector<std::string>& args) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    std::vector<std::string> argv{ELASTICA_EXE};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> cargv;
    for (std::string& a : argv) cargv.push_back(a.data());
    cargv.push_back(nullptr);
    const int rc = posix_spawn(&pid_, ELASTICA_EXE, &actions, nullptr, cargv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    out_ = fds[0];
    if (rc != 0) throw std::runtime_error("cannot start " ELASTICA_EXE);
  }
  ~Child() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    close(out_);
  }

  // Reads output until it contains `text` (true) or the child closes its output or `seconds`
  // pass (false: a hung or failed child must fail the test, not hang it).
  bool waitFor(const std::string& text, double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (output_.find(text) == std::string::npos) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return false;
      pollfd p{out_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left.count())) <= 0) return false;
      char buf[4096];
      const ssize_t n = read(out_, buf, sizeof buf);
      if (n <= 0) return false;
      output_.append(buf, static_cast<size_t>(n));
    }
    return true;
  }

  // Sends `sig`, reads the rest of the output and returns the wait status.
  int interrupt(int sig) {
    kill(pid_, sig);
    waitFor("\x01never printed", 60);  // until the output closes
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    return status;
  }

  const std::string& output() const { return output_; }

 private:
  pid_t pid_ = -1;
  int out_ = -1;
  std::string output_;
};

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
