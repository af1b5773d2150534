// SPDX-License-Identifier: GPL-3.0-or-later
// The command-line options of the fair, fill and curvature commands, generated from the options
// table (app/filter_spec.h): one option per row with a CLI flag, its type, range, default and
// help from the row. The values given are collected by row and turned into options by
// app::readJob, as every face's are.
#pragma once

#include <elastica/app/filter_spec.h>

#include <CLI/CLI.hpp>

namespace elastica::cli {

/// Registers an option for every row of filter `filter` that has a CLI flag, in the table's order:
/// a number checked against the row's range when parsed, an enum by its words (app/choices.h), a
/// Bool row as a flag that sets the opposite of the core's default. Values given go into `given`.
void addTableOptions(CLI::App& cmd, app::FilterId filter, app::ParamValues& given);

/// The checks of a flow command's options against each other, after parsing: an option of one
/// scheme is refused with another, and the bilaplacian flow without --scheme runs explicit.
void addFlowChecks(CLI::App& cmd, app::FilterId filter, app::ParamValues& given);

}  // namespace elastica::cli
