// SPDX-License-Identifier: GPL-3.0-or-later
// The `elastica` help as a reader wants it, not as CLI11 stores it: an enum option lists its words
// once ("{elastica|lmc|bilaplacian}", not "ENUM:value in {bilaplacian->2,...} OR {2,0,1}"), a
// range reads "INT >= 0", a default "(default 0.05)", and a negative flag is shown without its
// stored value ("--no-remesh", not "--no-remesh{false}").
#pragma once

#include <CLI/CLI.hpp>

namespace elastica::cli {

class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_name(const CLI::Option* opt, bool positional) const override;
  std::string make_option_opts(const CLI::Option* opt) const override;
};

/// A CLI11 parse error as the user should read it: "--flow: 'bogus' is not one of bilaplacian,
/// elastica, lmc" rather than the transformer's "Check bogus value in {bilaplacian->2,...} FAILED".
std::string readableParseError(const std::string& what);

/// For an argument `app` did not expect that looks like an option ("--featur-size"), the option of
/// the chosen command it most likely means (" (did you mean --feature-size?)"), else "".
std::string optionSuggestion(const CLI::App& app, const std::vector<std::string>& unexpected);

}  // namespace elastica::cli
