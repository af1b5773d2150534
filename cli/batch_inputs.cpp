// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch_inputs.h"

#include <elastica/errors.h>
#include <elastica/io/mesh_reader.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

namespace elastica::cli {
namespace fs = std::filesystem;

namespace {

bool isMeshName(const fs::path& p) {
  try {
    io::formatFromExtension(p.string());
    return true;
  } catch (const IoError&) {
    return false;
  }
}

bool isHidden(const fs::path& p) {
  const std::string name = p.filename().string();
  return !name.empty() && name[0] == '.';
}

// True if `p` is `dir` or inside it (both made absolute and normal).
bool isInside(const fs::path& p, const fs::path& dir) {
  std::string a = fs::weakly_canonical(p).string(), d = fs::weakly_canonical(dir).string();
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  while (a.size() > 1 && a.back() == '/') a.pop_back();
  return a == d || a.rfind(d + "/", 0) == 0;
}

void searchFolder(const fs::path& folder, const fs::path& outputDir, std::vector<std::string>& found) {
  for (auto it = fs::recursive_directory_iterator(folder); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path& p = it->path();
    if (isHidden(p) || (it->is_directory() && isInside(p, outputDir))) {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && isMeshName(p)) found.push_back(p.string());
  }
}

int envInt(const char* name, int fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  char* end = nullptr;
  const long x = std::strtol(v, &end, 10);
  if (*end != '\0') throw CLI::ValidationError("--shard", std::string(name) + "=" + v + " is not a number: pass --shard I/N");
  return static_cast<int>(x);
}

}  // namespace

std::vector<std::string> findMeshInputs(const std::vector<std::string>& given, const std::string& outputDir) {
  std::vector<std::string> found;
  for (const std::string& g : given) {
    std::error_code ec;
    if (fs::is_directory(g, ec)) searchFolder(g, outputDir, found);
    else if (fs::exists(g, ec)) found.push_back(g);
    else throw IoError(g + ": no such file or folder");
  }
  std::sort(found.begin(), found.end());
  // One run per file, however it was named.
  std::set<fs::path> seen;
  std::vector<std::string> unique;
  for (const std::string& f : found)
    if (seen.insert(fs::weakly_canonical(f)).second) unique.push_back(f);
  return unique;
}

std::vector<BatchItem> assignOutputs(const std::vector<std::string>& inputs, const std::string& outputDir,
                                     const std::string& format) {
  std::vector<BatchItem> items;
  std::map<std::string, std::string> owner;  // output → the input that writes it
  for (const std::string& in : inputs) {
    const std::string out = (fs::path(outputDir) / (fs::path(in).stem().string() + "." + format)).string();
    const auto [it, fresh] = owner.emplace(out, in);
    if (!fresh) throw IoError(in + " and " + it->second + " would both write " + out + ": rename one or run them apart");
    items.push_back({in, out});
  }
  return items;
}

Shard parseShard(const std::string& text) {
  Shard s;
  char slash = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &s.index, &slash, &s.count, &rest) != 3 || slash != '/' || s.count < 1 ||
      s.index < 1 || s.index > s.count)
    throw CLI::ValidationError("--shard", "'" + text + "' is not I/N with 1 <= I <= N (e.g. 2/4)");
  return s;
}

Shard shardFromEnvironment() {
  const int id = envInt("SLURM_ARRAY_TASK_ID", -1);
  if (id < 0) return {};
  const int count = envInt("SLURM_ARRAY_TASK_COUNT", 0), first = envInt("SLURM_ARRAY_TASK_MIN", 0),
            step = envInt("SLURM_ARRAY_TASK_STEP", 1), last = envInt("SLURM_ARRAY_TASK_MAX", -1);
  // A range's task IDs run first, first + step, …: the k-th of `count` is shard k + 1. A list
  // (1,3,7) is no range: its IDs do not say which k they are.
  const bool range = step > 0 && (last < 0 || (last - first) / step + 1 == count);
  const int k = range && (id - first) % step == 0 ? (id - first) / step : -1;
  if (count < 1 || k < 0 || k >= count)
    throw CLI::ValidationError("--shard", "cannot tell this task's shard from SLURM_ARRAY_TASK_ID=" + std::to_string(id) +
                                              " (an array given as a list?): pass --shard I/N");
  return {k + 1, count, "SLURM_ARRAY_TASK_ID=" + std::to_string(id)};
}

std::vector<BatchItem> itemsOfShard(const std::vector<BatchItem>& all, const Shard& shard) {
  std::vector<BatchItem> mine;
  for (std::size_t k = 0; k < all.size(); ++k)
    if (static_cast<int>(k % static_cast<std::size_t>(shard.count)) == shard.index - 1) mine.push_back(all[k]);
  return mine;
}

}  // namespace elastica::cli
