// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch_runner.h"

#include <elastica/errors.h>

#include <fcntl.h>
#include <pthread.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <map>

extern char** environ;

namespace elastica::cli {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kKillGraceSeconds = 10;

struct Running {
  int job;
  Clock::time_point start;
  bool terminated = false;  // sent SIGTERM at the time limit
  Clock::time_point killAt;
};

// The environment with `extra` ("NAME=value") replacing or adding entries.
std::vector<std::string> environmentWith(const std::vector<std::string>& extra) {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string s = *e;
    const bool replaced = std::any_of(extra.begin(), extra.end(), [&](const std::string& x) {
      return s.compare(0, x.find('=') + 1, x, 0, x.find('=') + 1) == 0;
    });
    if (!replaced) env.push_back(s);
  }
  env.insert(env.end(), extra.begin(), extra.end());
  return env;
}

std::vector<char*> pointers(std::vector<std::string>& v) {
  std::vector<char*> p;
  for (std::string& s : v) p.push_back(s.data());
  p.push_back(nullptr);
  return p;
}

// fork + exec with everything prepared before the fork (the child calls only async-signal-safe functions).
pid_t start(JobLaunch launch, const sigset_t& childMask) {
  std::vector<std::string> env = environmentWith(launch.environment);
  std::vector<char*> argv = pointers(launch.argv), envp = pointers(env);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw IoError(std::string("cannot start a job: ") + std::strerror(errno));
  if (pid > 0) return pid;
  pthread_sigmask(SIG_SETMASK, &childMask, nullptr);
  prctl(PR_SET_PDEATHSIG, SIGTERM);  // a batch killed outright takes its jobs with it
  if (getppid() != parent) _exit(127);
  const int in = open("/dev/null", O_RDONLY);
  const int out = open(launch.stdoutPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int err = open(launch.stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (in < 0 || out < 0 || err < 0) _exit(127);
  dup2(in, STDIN_FILENO);
  dup2(out, STDOUT_FILENO);
  dup2(err, STDERR_FILENO);
  execve(launch.program.c_str(), argv.data(), envp.data());
  _exit(127);
}

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Sends SIGTERM to children past the time limit, SIGKILL to those still there after the grace.
void enforceTimeLimit(std::map<pid_t, Running>& running, double maxSeconds) {
  if (maxSeconds <= 0) return;
  for (auto& [pid, r] : running) {
    if (!r.terminated && secondsSince(r.start) > maxSeconds) {
      kill(pid, SIGTERM);
      r.terminated = true;
      r.killAt = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(kKillGraceSeconds));
    } else if (r.terminated && Clock::now() > r.killAt) {
      kill(pid, SIGKILL);
    }
  }
}

// Seconds until the first child passes the time limit (or its grace ends), at most one (the ticks).
double secondsToNextDeadline(const std::map<pid_t, Running>& running, double maxSeconds) {
  double wait = 1;
  if (maxSeconds <= 0) return wait;
  for (const auto& entry : running) {
    const Running& r = entry.second;
    const double left = r.terminated ? std::chrono::duration<double>(r.killAt - Clock::now()).count()
                                     : maxSeconds - secondsSince(r.start);
    wait = std::min(wait, std::max(left, 0.001));
  }
  return wait;
}

// Waits for the next signal in `set`, at most `seconds`; 0 if none came.
int waitSignal(const sigset_t& set, double seconds) {
  const long ns = static_cast<long>(seconds * 1e9);
  const timespec t{ns / 1000000000L, ns % 1000000000L};
  siginfo_t info;
  const int sig = sigtimedwait(&set, &info, &t);
  return sig < 0 ? 0 : sig;
}

}  // namespace

int runJobs(int count, const JobPoolOptions& opt, const std::function<JobLaunch(int)>& launchOf,
            const std::function<void(int, const JobEnd&)>& onEnd, const std::function<void()>& onTick) {
  // The signals are taken synchronously (sigtimedwait), not by a handler: no state is shared with one.
  sigset_t set, old;
  sigemptyset(&set);
  for (int s : {SIGCHLD, SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
  pthread_sigmask(SIG_BLOCK, &set, &old);
  std::map<pid_t, Running> running;
  int next = 0, stoppedBy = 0;
  try {
    while (true) {
      while (!stoppedBy && next < count && static_cast<int>(running.size()) < std::max(1, opt.jobs)) {
        running[start(launchOf(next), old)] = Running{next, Clock::now(), false, {}};
        ++next;
      }
      if (running.empty()) break;
      const int sig = waitSignal(set, secondsToNextDeadline(running, opt.maxSeconds));
      if (sig == SIGINT || sig == SIGTERM || sig == SIGHUP) {
        for (const auto& entry : running) kill(entry.first, stoppedBy ? SIGKILL : sig);
        if (!stoppedBy) stoppedBy = sig;
      }
      for (auto it = running.begin(); it != running.end();) {
        int status = 0;
        if (waitpid(it->first, &status, WNOHANG) != it->first) {
          ++it;
          continue;
        }
        JobEnd end;
        if (WIFEXITED(status)) end.exitCode = WEXITSTATUS(status);
        if (WIFSIGNALED(status)) end.signal = WTERMSIG(status);
        end.timedOut = it->second.terminated;
        end.stopping = stoppedBy != 0;
        end.seconds = secondsSince(it->second.start);
        const int job = it->second.job;
        it = running.erase(it);
        onEnd(job, end);
      }
      enforceTimeLimit(running, opt.maxSeconds);
      onTick();
    }
  } catch (...) {
    for (const auto& entry : running) kill(entry.first, SIGTERM);
    for (const auto& entry : running) waitpid(entry.first, nullptr, 0);
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
    throw;
  }
  // Signals still pending are taken here: a late Ctrl-C still counts, a late SIGCHLD is dropped.
  const timespec zero{0, 0};
  siginfo_t info;
  for (int sig; (sig = sigtimedwait(&set, &info, &zero)) > 0;)
    if (sig != SIGCHLD && !stoppedBy) stoppedBy = sig;
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return stoppedBy;
}

}  // namespace elastica::cli
