// SPDX-License-Identifier: GPL-3.0-or-later
// Running a batch's jobs as child processes, a few at a time: each with a time limit, all of them
// told when the batch is interrupted.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace elastica::cli {

/// One child: its argv (argv[0] is the program run), where its stdout and stderr go, its extra
/// environment ("NAME=value", replacing the inherited value).
struct JobLaunch {
  std::string program;
  std::vector<std::string> argv, environment;
  std::string stdoutPath, stderrPath;
};

struct JobEnd {
  int exitCode = -1;      // when it exited
  int signal = 0;         // when a signal ended it
  bool timedOut = false;  // it was stopped at the time limit
  bool stopping = false;  // it ended after the pool was interrupted
  double seconds = 0;     // wall time from start to end
};

struct JobPoolOptions {
  int jobs = 1;           // children at once
  double maxSeconds = 0;  // per child, 0 for none: then SIGTERM, and SIGKILL 10 s later
};

/// Runs jobs 0 … count-1 in order, at most `opt.jobs` at once, calling `onEnd` as each ends and
/// `onTick` at least once a second. A SIGINT, SIGTERM or SIGHUP stops launching and is passed on to the
/// running children, which are waited for (a second one kills them). Returns that signal, or 0
/// when every job ran. The children get the signal mask this was called with, and SIGTERM if this
/// process dies. @throws IoError if a child cannot be started.
int runJobs(int count, const JobPoolOptions& opt, const std::function<JobLaunch(int)>& launchOf,
            const std::function<void(int, const JobEnd&)>& onEnd, const std::function<void()>& onTick);

}  // namespace elastica::cli
