// Running the real `elastica` binary from a test (ELASTICA_EXE is set by tests/CMakeLists.txt).
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

inline CommandResult runElastica(const std::string& args) {
  const std::string cmd = std::string(ELASTICA_EXE) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), out};
}

}  // namespace elastica::test
