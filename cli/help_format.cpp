#include "help_format.h"

#include <regex>

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
