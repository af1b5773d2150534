// SPDX-License-Identifier: GPL-3.0-or-later
// The record a batch keeps beside each output, so a second run can tell what is done: the program,
// the command and its options, and digests of the input's and the output's bytes.
#pragma once

#include "batch_inputs.h"

#include <string>
#include <vector>

namespace elastica::cli {

/// A 64-bit FNV-1a digest of a file's bytes, as 16 hex digits (to notice a changed file, not to
/// resist an attacker). @throws IoError if the file cannot be read.
std::string fileDigest(const std::string& path);

/// What makes an output besides its input: the program and the command line it runs.
struct RunKey {
  std::string program;               // version and the executable's digest
  std::string command;               // e.g. "fair"
  std::vector<std::string> options;  // COMMAND's options, as forwarded
};

/// The record of `output`: <its folder>/.elastica-batch/<its name>.json.
std::string recordPath(const std::string& output);

/// True if `item.output` has a record made by `key` from an input whose digest is `inputDigest`,
/// and the output still has the bytes recorded. Any missing or unreadable piece means not done.
bool isDone(const BatchItem& item, const RunKey& key, const std::string& inputDigest);

/// Writes the record of `item.output`, just written by `key` from that input (atomically, after the
/// output: a run stopped between the two leaves an output without a record, which is redone).
/// @throws IoError.
void writeRecord(const BatchItem& item, const RunKey& key, const std::string& inputDigest);

}  // namespace elastica::cli
