// SPDX-License-Identifier: GPL-3.0-or-later
// Writing files so that a failure never leaves a half-written output: the data goes to a
// temporary file in the destination directory, renamed over the destination only when complete.
#pragma once

#include <functional>
#include <string>

namespace elastica::io {

/// Checks, before any work is done, that `output` can be written and is not `input`.
/// @throws IoError naming the problem (missing directory, not writable, a directory, same file).
void checkOutputPath(const std::string& output, const std::string& input = {});

/// Calls `write(temporaryPath)`, then renames the temporary file to `path`. If `write` throws,
/// the temporary file is removed and `path` is untouched. While it exists, the temporary file is
/// registered for removePendingTemporaryFiles().
/// @throws IoError if the temporary file cannot be created or renamed; whatever `write` throws.
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

/// Deletes the temporary files that writeAtomically calls are writing at this moment (their
/// destinations are untouched) and returns how many it deleted. Async-signal-safe: meant for a
/// signal handler, which cannot unwind the stack to the temporaries' destructors.
int removePendingTemporaryFiles() noexcept;

/// For programs (the plugin leaves signals to its host): on SIGINT, SIGTERM or SIGHUP, delete the
/// pending temporary files, print `<program>: interrupted by SIG…` on stderr and die of the same
/// signal (so a shell sees 128 + its number, 130 for Ctrl-C, and a script running the program
/// stops too). A signal ignored when this is called (nohup, background jobs) stays ignored.
/// `program` must outlive the process (a string literal).
void installInterruptHandlers(const char* program);

}  // namespace elastica::io
