// Running a program from a test and capturing what it prints.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace elastica::test {

struct CommandResult {
  int exitCode;
  std::string output;  // stdout and stderr together
};

/// Runs `command` through the shell; a signal shows as exit code 128 + signal.
inline CommandResult runCommand(const std::string& command) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return {-1, "popen failed"};
  std::string out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), out};
}

/// `s` in single quotes for the shell (paths here hold no single quote).
inline std::string quoted(const std::string& s) { return "'" + s + "'"; }

}  // namespace elastica::test
