// SPDX-License-Identifier: GPL-3.0-or-later
// Face selections given as a text file of face indices, for users without MeshLab's PLY flags:
// `elastica fair --selected-faces FILE`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace elastica::cli {

/// Reads 0-based face indices from `path`: integers separated by white space or commas, `#` to
/// the end of a line is a comment, repeats are allowed. Returns one flag per face (1 = listed).
/// @throws IoError if the file cannot be read, and InvalidInputError naming the line for anything
///         that is not an index in [0, faceCount), or if no index is listed.
std::vector<std::uint8_t> readFaceIndexFile(const std::string& path, int faceCount);

}  // namespace elastica::cli
