// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow_options.h"

#include <elastica/app/choices.h>

#include <cstdint>
#include <limits>
#include <map>

namespace elastica::cli {
namespace {

// The row's range as a CLI11 check, described as the help shows it ("in 0..8", ">= 0", "> 0").
// A length (AbsPerc) also takes "auto" (its default).
CLI::Validator range(const app::ParamSpec& p) {
  const double lo = p.minValue;
  const double hi = p.maxValue;
  const bool length = p.type == app::ParamType::AbsPerc;
  const bool open = p.minExclusive;
  auto str = [](double x) { return CLI::detail::to_string(x); };
  const std::string text = hi < std::numeric_limits<double>::infinity() ? "in " + str(lo) + ".." + str(hi)
                                                                        : (open ? "> " : ">= ") + str(lo);
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        if (length && s == "auto") {
          s = CLI::detail::to_string(app::kAutoFeatureSize);
          return {};
        }
        double x = 0;
        if (!CLI::detail::lexical_cast(s, x) || !((open ? x > lo : x >= lo) && x <= hi)) return "Value " + s + " is not " + text;
        return {};
      },
      text);
}

}  // namespace

void addTableOptions(CLI::App& cmd, app::FilterId filter, app::ParamValues& given) {
  const app::JobOptions defaults;
  for (const app::ParamSpec& p : app::filterSpec(filter, {}).params) {
    if (p.cliFlag.empty()) continue;
    const std::string key = p.key();
    const std::string names = p.cliAlias.empty() ? p.cliFlag : p.cliFlag + "," + p.cliAlias;
    const std::string help = p.cliHelp.empty() ? p.tooltip : p.cliHelp;
    const double core = p.get(defaults);  // the CLI starts from the core's defaults
    app::ParamValues* values = &given;
    switch (p.type) {
      case app::ParamType::Bool:
        cmd.add_flag_function(names, [values, key, core](std::int64_t) { values->set(key, core != 0 ? 0 : 1); }, help);
        break;
      case app::ParamType::Enum: {
        std::map<std::string, int> words;
        for (std::size_t i = 0; i < p.enumWords.size(); ++i) words.emplace(p.enumWords[i], static_cast<int>(i));
        cmd.add_option_function<int>(names, [values, key](const int& i) { values->set(key, i); }, help)
            ->type_name("ENUM")
            ->transform(CLI::CheckedTransformer(words, CLI::ignore_case));
        break;
      }
      case app::ParamType::Int: {
        CLI::Option* o =
            cmd.add_option_function<long long>(names, [values, key](const long long& x) { values->set(key, double(x)); }, help)
                ->check(range(p));
        if (core != 0) o->default_str(CLI::detail::to_string(static_cast<long long>(core)));
        break;
      }
      case app::ParamType::Float:
      case app::ParamType::AbsPerc: {
        CLI::Option* o =
            cmd.add_option_function<double>(names, [values, key](const double& x) { values->set(key, x); }, help)
                ->transform(range(p));  // may turn "auto" into its number
        if (p.type == app::ParamType::AbsPerc && core == app::kAutoFeatureSize) o->default_str("auto");
        else if (core != 0) o->default_str(CLI::detail::to_string(core));
        break;
      }
    }
  }
}

void addFlowChecks(CLI::App& cmd, app::FilterId filter, app::ParamValues& given) {
  CLI::App* command = &cmd;
  app::ParamValues* values = &given;
  cmd.parse_complete_callback([command, values, filter] {
    const app::FilterSpec spec = app::filterSpec(filter, {});
    // The bilaplacian comparison flow is the paper's explicit iteration: without --scheme it runs
    // explicit rather than failing on the default.
    const app::JobOptions asked = app::readJob(spec, *values, app::Caller::Cli);
    const FlowOptions& opt = filter == app::FilterId::FillHoles ? asked.fill.flow : asked.flow;
    if (opt.flow == FlowType::Bilaplacian && command->count("--scheme") == 0)
      values->set(spec.param("scheme")->key(), app::indexOf(Scheme::Explicit));
    const Scheme scheme = opt.flow == FlowType::Bilaplacian && command->count("--scheme") == 0 ? Scheme::Explicit : opt.scheme;
    // Some options belong to one scheme: asking for one with the other scheme is an error, not a
    // silent ignore (--energy-tol means the same in both).
    const CLI::Option* noRemesh = command->get_option_no_throw("--no-remesh");  // fair's, not fill's
    if (scheme == Scheme::Explicit && noRemesh && noRemesh->count() > 0)
      throw CLI::ValidationError("--no-remesh", "applies to the vector and semi-implicit schemes only (the explicit one never remeshes)");
    if (scheme != Scheme::SemiImplicit && command->count("--shape-tol") > 0)
      throw CLI::ValidationError("--shape-tol", "applies to the semi-implicit scheme only (add --scheme semi-implicit)");
    if (scheme != Scheme::Explicit && command->count("--step-factor") > 0)
      throw CLI::ValidationError("--step-factor",
                                 "sets the explicit scheme's step only (the other schemes adapt their own)");
  });
}

}  // namespace elastica::cli
