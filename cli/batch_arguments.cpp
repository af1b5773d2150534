// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch_arguments.h"

namespace elastica::cli {
namespace {

// The option name of a word ("--steps=3" → "--steps", "-j2" → "-j"), or "" if it is no option.
std::string optionName(const std::string& w) {
  if (w.size() < 2 || w[0] != '-') return {};
  if (w[1] == '-') return w.substr(0, w.find('='));
  return w.substr(0, 2);
}

// True if the word carries its value ("--log=x", "-j2").
bool valueAttached(const std::string& w, const std::string& name) { return w.size() > name.size(); }

const CLI::Option* find(const CLI::App& app, const std::string& name) {
  const CLI::Option* o = app.get_option_no_throw(name);
  return o && !o->get_positional() ? o : nullptr;
}

}  // namespace

BatchWords splitBatchWords(const std::vector<std::string>& words, const CLI::App& batch, const CLI::App& command) {
  BatchWords out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& w = words[i];
    if (w == "--") {
      out.inputs.insert(out.inputs.end(), words.begin() + static_cast<long>(i) + 1, words.end());
      break;
    }
    const std::string name = optionName(w);
    if (name.empty()) {
      out.inputs.push_back(w);
      continue;
    }
    // Batch's own first: its -o is the output folder, not COMMAND's output file.
    const CLI::Option* o = find(batch, name);
    std::vector<std::string>* to = &out.batchOptions;
    if (!o) {
      o = find(command, name);
      to = &out.commandOptions;
      if (o && (o->check_name("--report") || o->check_name("--progress") || o->check_name("--help")))
        throw CLI::ExtrasError("batch: " + name + " is not forwarded: batch writes its own --log and progress line",
                               CLI::ExitCodes::ExtrasError);
    }
    if (!o)
      throw CLI::ExtrasError("batch: " + name + " is an option of neither 'batch' nor '" + command.get_name() + "'",
                             CLI::ExitCodes::ExtrasError);
    to->push_back(w);
    if (o->get_items_expected_max() > 0 && !valueAttached(w, name)) {
      if (i + 1 >= words.size()) throw CLI::ArgumentMismatch(name + ": a value is needed");
      to->push_back(words[++i]);
    }
  }
  return out;
}

}  // namespace elastica::cli
