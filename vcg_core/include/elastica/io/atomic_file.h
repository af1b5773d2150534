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
/// the temporary file is removed and `path` is untouched.
/// @throws IoError if the temporary file cannot be created or renamed; whatever `write` throws.
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace elastica::io
