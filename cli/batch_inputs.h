// SPDX-License-Identifier: GPL-3.0-or-later
// What a batch works on: the mesh files found in the inputs, the output each one gets, and the
// shard of them this process runs.
#pragma once

#include <string>
#include <vector>

namespace elastica::cli {

struct BatchItem {
  std::string input;   // as found: a path given, or a folder given joined with the file's path in it
  std::string output;  // DIR/<stem>.<format>
};

/// The inputs: each file given, and every .ply/.off/.obj/.stl file (any case) in each folder given,
/// searched recursively, skipping hidden names and anything inside `outputDir`. Sorted by path and
/// without repeats, so every shard sees the same list. @throws IoError for a missing input.
std::vector<std::string> findMeshInputs(const std::vector<std::string>& given, const std::string& outputDir);

/// Each input with its output `outputDir/<stem>.<format>`.
/// @throws IoError naming both inputs if two of them would write the same output.
std::vector<BatchItem> assignOutputs(const std::vector<std::string>& inputs, const std::string& outputDir,
                                     const std::string& format);

/// Shard `index` of `count` (1-based): a fixed partition of a sorted list, item k to shard k mod count + 1.
struct Shard {
  int index = 1, count = 1;
  std::string from;  // where it came from, e.g. "SLURM_ARRAY_TASK_ID=3" (empty for --shard or none)
};

/// "I/N" with 1 <= I <= N. @throws CLI::ValidationError otherwise.
Shard parseShard(const std::string& text);

/// The shard of a Slurm array task (SLURM_ARRAY_TASK_ID, _COUNT, _MIN, _MAX and _STEP), or 1/1
/// outside one. @throws CLI::ValidationError if the array is no range (a list such as 1,3,7).
Shard shardFromEnvironment();

/// The items of `all` that belong to `shard`, in order.
std::vector<BatchItem> itemsOfShard(const std::vector<BatchItem>& all, const Shard& shard);

}  // namespace elastica::cli
