// SPDX-License-Identifier: GPL-3.0-or-later
#include "help_format.h"

#include <algorithm>
#include <regex>
#include <string>
#include <vector>

namespace elastica::cli {
namespace {

// "ENUM:value in {bilaplacian->2,elastica->0,lmc->1} OR {2,0,1}" -> "{bilaplacian|elastica|lmc}".
std::string enumWords(const std::string& type) {
  std::string words;
  static const std::regex word(R"(([A-Za-z][A-Za-z0-9_-]*)->)");
  for (std::sregex_iterator it(type.begin(), type.end(), word), end; it != end; ++it)
    words += (words.empty() ? "" : "|") + (*it)[1].str();
  return "{" + words + "}";
}

// "INT:>= 0" -> "INT >= 0", "FLOAT:NONNEGATIVE" -> "FLOAT >= 0", "INT:in 0..8" -> "INT in 0..8".
std::string typeText(std::string type) {
  if (type.rfind("ENUM:", 0) == 0) return enumWords(type);
  type = std::regex_replace(type, std::regex("NONNEGATIVE"), ">= 0");
  type = std::regex_replace(type, std::regex("POSITIVE"), "> 0");
  return std::regex_replace(type, std::regex(":"), " ");
}

}  // namespace

std::string readableParseError(const std::string& what) {
  static const std::regex check(R"(Check (.*) value in (\{[^}]*\}) OR \{[^}]*\} FAILED)");
  std::smatch m;
  if (!std::regex_search(what, m, check)) return what;
  std::string words = enumWords("ENUM:" + m[2].str());
  words = std::regex_replace(words.substr(1, words.size() - 2), std::regex("\\|"), ", ");
  return m.prefix().str() + "'" + m[1].str() + "' is not one of " + words + m.suffix().str();
}

namespace {

// The edit distance (insertions, deletions, substitutions) between two words.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string optionSuggestion(const CLI::App& app, const std::vector<std::string>& unexpected) {
  std::vector<const CLI::App*> commands = {&app};
  for (const CLI::App* sub : app.get_subcommands()) commands.push_back(sub);
  for (const std::string& arg : unexpected) {
    if (arg.rfind("--", 0) != 0) continue;
    const std::string word = arg.substr(0, arg.find('='));
    std::string best;
    std::size_t bestDistance = std::max<std::size_t>(3, word.size() / 4) + 1;  // a typo, not another word
    for (const CLI::App* command : commands)
      for (const CLI::Option* o : command->get_options())
        for (const std::string& name : o->get_lnames()) {
          const std::size_t d = editDistance(word, "--" + name);
          if (d < bestDistance) bestDistance = d, best = "--" + name;
        }
    if (!best.empty()) return " (did you mean " + best + "?)";
  }
  return {};
}

std::string HelpFormatter::make_option_name(const CLI::Option* opt, bool positional) const {
  // A flag declared "--no-remesh{false}" stores false; the user types "--no-remesh".
  return std::regex_replace(CLI::Formatter::make_option_name(opt, positional), std::regex(R"(\{[^}]*\})"), "");
}

std::string HelpFormatter::make_option_opts(const CLI::Option* opt) const {
  if (!opt->get_option_text().empty() || opt->get_type_size() == 0) return CLI::Formatter::make_option_opts(opt);
  std::string out;
  if (!opt->get_type_name().empty()) out += " " + typeText(opt->get_type_name());
  if (!opt->get_default_str().empty()) out += " (default " + opt->get_default_str() + ")";
  if (opt->get_required()) out += " REQUIRED";
  for (const CLI::Option* other : opt->get_excludes()) out += " (not with " + other->get_name() + ")";
  return out;
}

}  // namespace elastica::cli
