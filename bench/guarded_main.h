// SPDX-License-Identifier: GPL-3.0-or-later
// The main() of a benchmark tool: `--help` prints its usage, and a bad argument or an unreadable
// mesh ends with one line on stderr and exit status 1 instead of an abort on an uncaught exception.
#pragma once

#include <cstdio>
#include <cstring>
#include <exception>

namespace elastica::bench {

/// Runs `run(argc, argv)` (which prints its usage line when called without arguments) for the tool `name`.
inline int guardedMain(const char* name, int (*run)(int, char**), int argc, char** argv) {
  try {
    if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
      char* usage[] = {argv[0], nullptr};
      run(1, usage);
      return 0;
    }
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 1;
  }
}

}  // namespace elastica::bench
