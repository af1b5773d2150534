// SPDX-License-Identifier: GPL-3.0-or-later
// The words of `elastica batch COMMAND -o DIR [options of COMMAND] INPUT...`, sorted into the batch's
// own options, COMMAND's options (forwarded to each run as given) and the inputs. COMMAND's options
// are recognised from its own CLI11 definition, so batch never lists them.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace elastica::cli {

struct BatchWords {
  std::vector<std::string> batchOptions;    // e.g. {"-j", "2", "--log=run.jsonl"}
  std::vector<std::string> commandOptions;  // e.g. {"--max-steps", "50", "--ascii"}
  std::vector<std::string> inputs;          // files and folders, in the order given
};

/// Sorts `words` (what follows COMMAND): an option of `batch` (with its value) goes to batchOptions,
/// an option of `command` to commandOptions, anything else (and all after `--`) to inputs. Options
/// batch sets itself on each run (-o, --report, --progress) are refused.
/// @throws CLI::ExtrasError for an option neither knows, CLI::ArgumentMismatch for a missing value.
BatchWords splitBatchWords(const std::vector<std::string>& words, const CLI::App& batch, const CLI::App& command);

}  // namespace elastica::cli
