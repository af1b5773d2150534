// SPDX-License-Identifier: GPL-3.0-or-later
// The options table: every parameter of the three filters, one row each, with its name on every
// face (the options field, the .mlx name, the CLI flag, the Python keyword, the Blender property),
// its type, range, default and help. Every face is generated from it: the MeshLab dialogs and
// `elastica run` (the rows with an .mlx name), the CLI's options (cli/flow_options.cpp), the
// Python keywords and filters() (python/elastica_module.cpp) and, through filters(), the Blender
// redo panels. Enumerated values come from choices.h. Qt-free and vcglib-free.
//
// Names are fixed for good: .mlx scripts, command lines, Python scripts and Blender files key on
// them, and Debian's meshlabserver aborts on a script that omits an .mlx parameter, so scripts
// list every one. Add a row only when an issue asks for it, and never rename one.
#pragma once

#include <elastica/app/fairing_amount.h>
#include <elastica/flow.h>
#include <elastica/hole_filling.h>
#include <elastica/mesh_curvature.h>

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace elastica::app {

/// The filters, in menu order. The values are the plugin's FilterIDType ids.
enum class FilterId { Fairing = 0, FillHoles = 1, Curvature = 2 };

/// Who gives a value, and so how a message names the parameter: a face, or the C++ API (the
/// options structs, named by field).
enum class Caller { MeshLab, Cli, Python, Blender, Api };

/// The parameter kinds, as MeshLab names them in .mlx files (RichBool, RichInt, ...).
/// AbsPerc is a length in the mesh's units, on every face (MeshLab's dialog also shows it as a
/// percentage of the bounding-box diagonal), and what a report prints: one unit everywhere.
enum class ParamType { Bool, Int, Float, Enum, AbsPerc };

/// "RichBool", "RichInt", "RichFloat", "RichEnum", "RichAbsPerc".
const char* richTypeName(ParamType t);

/// What a filter's parameters set: the core's options of its run and what the face does around it.
struct JobOptions {
  JobOptions() { flow.featureSize = kAutoFeatureSize; }
  /// Discrete Elastica Fairing; its featureSize starts "auto" (fairing_amount.h), which runFairing
  /// sizes from the mesh: a default run keeps the model.
  FlowOptions flow;
  HoleFillOptions fill;                ///< Fill Holes with Discrete Elastica
  CurvatureMeasureOptions curvature;   ///< Discrete Elastica Curvature
  bool selected = false;               ///< fairing: only the selected faces move
  bool colorByMeanCurvature = false;   ///< store H as vertex quality and colour
  bool selectNewFaces = true;          ///< fill: only the new faces are selected afterwards
};

/// One row of the options table. A name left empty: the face does not have the parameter.
struct ParamSpec {
  std::string field;            ///< the JobOptions member it sets: "flow.maxSteps"
  std::string name;             ///< the .mlx name (MeshLab's dialog, `elastica run`)
  std::string cliFlag;          ///< "--max-steps"; a Bool row's flag sets the opposite of the default
  std::string cliAlias;         ///< an older spelling the CLI still takes ("--remesh" for --flip-edges)
  std::string keyword;          ///< the Python keyword argument
  std::string blenderProperty;  ///< the Blender operator's property
  ParamType type = ParamType::Bool;
  /// The dialogs' default (MeshLab, Blender): bool as 0/1, int, float, or the enum index. The CLI
  /// and Python start from the core's defaults (`get` of a default JobOptions); they differ only
  /// where an interactive session needs a bound (a 60 s time limit, no step limit).
  double defaultValue = 0;
  std::vector<std::string> enumValues;  ///< Enum: MeshLab's menu entries, in .mlx index order
  std::vector<std::string> enumWords;   ///< Enum: the CLI's and Python's words, same order
  /// The dialog's field name, and the help under it and in its tooltip (also Python's and
  /// Blender's description): plain text without '<', '>' or '&' (MeshLab shows the help as Qt rich
  /// text but the tooltip as plain text; tested).
  std::string label;
  std::string tooltip;
  std::string cliHelp;  ///< the --help line (in the CLI's words, naming other flags)
  /// Int, Float, AbsPerc: the accepted range, checked in one place (checkValue) for every face.
  /// AbsPerc also takes kAutoFeatureSize (-1, "auto").
  double minValue = -std::numeric_limits<double>::infinity();
  double maxValue = std::numeric_limits<double>::infinity();
  bool minExclusive = false;  ///< the minimum itself is refused (> 0)
  std::string rangeHint;      ///< why the minimum, if it needs saying ("a hole has 3 edges or more")
  /// Writes a value (as in ParamValues) into its field, and reads it back (the core's default
  /// from a default JobOptions).
  std::function<void(JobOptions&, double)> set;
  std::function<double(const JobOptions&)> get;

  bool inMeshLab() const { return !name.empty(); }
  /// The key of its value in ParamValues: the .mlx name, else the field.
  const std::string& key() const { return name.empty() ? field : name; }
  /// The parameter as `caller` names it: "'Maximum steps' (maxSteps)", "--max-steps", "max_steps",
  /// "flow.maxSteps".
  std::string describe(Caller caller) const;
};

struct FilterSpec {
  FilterId id = FilterId::Fairing;
  std::string name;  ///< the menu entry and the .mlx filter name, fixed forever
  std::string info;  ///< HTML help shown at the top of MeshLab's dialog
  /// Every row: MeshLab's in its dialog's order (skip the rows without an .mlx name), the others
  /// among them where they read best in the CLI's --help.
  std::vector<ParamSpec> params;

  /// The row whose .mlx name is `name`, or nullptr.
  const ParamSpec* param(const std::string& name) const;
  /// The row with ParamSpec::key() `key`, or nullptr.
  const ParamSpec* row(const std::string& key) const;
};

/// What the defaults depend on: the mesh the filter is about to run on.
struct MeshFacts {
  int selectedFaces = 0;
  double diagonal = 0;  ///< of the bounding box (RichAbsPerc's 100 %)
  /// The fairing amount "auto" stands for on this mesh (autoFeatureSize over the selected faces if
  /// any, else all): the dialog's default feature size. 0 when unknown.
  double featureSize = 0;
};

/// Every filter, in menu order, with defaults for `mesh`.
std::vector<FilterSpec> allFilters(const MeshFacts& mesh);
FilterSpec filterSpec(FilterId id, const MeshFacts& mesh);
/// The filter called `name` (exact match, as meshlabserver matches), if it is one of ours.
std::optional<FilterId> findFilter(const std::string& name);

/// Parameter values of one filter application, by ParamSpec::key(). Floats from MeshLab are
/// stored as MeshLab holds them (float, widened to double) so the plugin and `elastica run`
/// compute with identical inputs.
class ParamValues {
 public:
  /// Every MeshLab parameter at its dialog default.
  static ParamValues defaults(const FilterSpec& spec);

  void set(const std::string& key, double value) { values_[key] = value; }
  bool has(const std::string& key) const { return values_.count(key) != 0; }

  /// @throws InvalidInputError if `key` has no value (a programming error in the caller).
  bool getBool(const std::string& key) const;
  int getInt(const std::string& key) const;
  double getFloat(const std::string& key) const;
  int getEnum(const std::string& key) const;

 private:
  double get(const std::string& key) const;
  std::map<std::string, double> values_;
};

/// Checks `value` of row `p` as `caller` gives it: in range (an AbsPerc length, or -1 for "auto"),
/// an Enum index in its table.
/// @throws InvalidInputError naming the parameter as `caller` does, its range and the value.
void checkValue(const ParamSpec& p, double value, Caller caller);

/// The options `v` stands for: a default JobOptions with every value of `v` checked (checkValue)
/// and written into its field.
/// @throws InvalidInputError as checkValue.
JobOptions readJob(const FilterSpec& spec, const ParamValues& v, Caller caller);

/// Checks the options every entry point's run needs against the table's ranges (the values the
/// rows read back, named by their fields), so a caller of the C++ API that filled the options
/// itself meets the checks the faces' values meet.
/// @throws InvalidInputError naming the field.
void checkOptions(FilterId id, const JobOptions& job);

}  // namespace elastica::app
