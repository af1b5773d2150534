// SPDX-License-Identifier: GPL-3.0-or-later
// Running the real `elastica` binary (ELASTICA_EXE is set by tests/CMakeLists.txt), or any command,
// from a test.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace elastica::test {

struct CommandResult {
  int exitCode;        // 128 + signal if the program was killed
  std::string output;  // stdout and stderr together
};

/// Runs `command` through the shell.
inline CommandResult runCommand(const std::string& command) {
  const std::string cmd = command + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), out};
}

inline CommandResult runElastica(const std::string& args) { return runCommand(std::string(ELASTICA_EXE) + " " + args); }

/// `s` in single quotes for the shell (paths here hold no single quote).
inline std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace elastica::test
