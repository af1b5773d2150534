// The MeshLab filters as data: names, parameters, defaults and help texts. Shared by the MeshLab
// plugin (which turns each parameter into a RichParameter) and `elastica run` (which reads them
// from .mlx scripts), so both see the same names, the same defaults and the same meaning.
// Qt-free and vcglib-free.
//
// Filter and parameter names are fixed for good: .mlx scripts key on them, and Debian's
// meshlabserver aborts on a script that omits a parameter, so scripts list every one. Add a
// parameter only when an issue asks for it, and never rename one.
#pragma once

#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace elastica::app {

/// The filters, in menu order. The values are the plugin's FilterIDType ids.
enum class FilterId { Fairing = 0, FillHoles = 1, Curvature = 2 };

/// The parameter kinds used, as MeshLab names them in .mlx files (RichBool, RichInt, ...).
/// AbsPerc is a length that MeshLab's dialog also shows as a percentage of the bounding-box
/// diagonal: its value (dialog, .mlx, ParamSpec::defaultValue for MeshFacts::diagonal) is the
/// length. The faces that take fractions of the diagonal (CLI, Python, Blender) multiply by it.
enum class ParamType { Bool, Int, Float, Enum, AbsPerc };

/// "RichBool", "RichInt", "RichFloat", "RichEnum", "RichAbsPerc".
const char* richTypeName(ParamType t);

struct ParamSpec {
  std::string name;                     ///< the .mlx name, fixed forever
  ParamType type = ParamType::Bool;
  double defaultValue = 0;              ///< bool as 0/1, int, float, or the enum index
  std::vector<std::string> enumValues;  ///< RichEnum entries, in index order
  /// The dialog's field description, and the help shown under it and as its tooltip: plain text,
  /// without '<', '>' or '&' (MeshLab shows the help as Qt rich text but the tooltip as plain
  /// text, so only text without markup characters reads the same in both; tested).
  std::string label;
  std::string tooltip;
  /// Int and Float: the accepted range, checked in one place (checkedNumber in filter_run.cpp)
  /// for the plugin's dialog and for .mlx scripts alike.
  double minValue = -std::numeric_limits<double>::infinity();
  double maxValue = std::numeric_limits<double>::infinity();
  std::string rangeHint;  ///< why the minimum, if it needs saying ("a hole has 3 edges or more")
};

struct FilterSpec {
  FilterId id = FilterId::Fairing;
  std::string name;  ///< the menu entry and the .mlx filter name, fixed forever
  std::string info;  ///< HTML help shown at the top of MeshLab's dialog
  std::vector<ParamSpec> params;

  /// The parameter called `name`, or nullptr.
  const ParamSpec* param(const std::string& name) const;
};

/// What the defaults depend on: the mesh the filter is about to run on.
struct MeshFacts {
  int selectedFaces = 0;
  double diagonal = 0;  ///< of the bounding box (RichAbsPerc's 100 %)
};

/// Every filter, in menu order, with defaults for `mesh`.
std::vector<FilterSpec> allFilters(const MeshFacts& mesh);
FilterSpec filterSpec(FilterId id, const MeshFacts& mesh);
/// The filter called `name` (exact match, as meshlabserver matches), if it is one of ours.
std::optional<FilterId> findFilter(const std::string& name);

/// Parameter values of one filter application, by name. Floats are stored as MeshLab holds them
/// (float, widened to double) so the plugin and `elastica run` compute with identical inputs.
class ParamValues {
 public:
  /// Every parameter at its default.
  static ParamValues defaults(const FilterSpec& spec);

  void set(const std::string& name, double value) { values_[name] = value; }
  bool has(const std::string& name) const { return values_.count(name) != 0; }

  /// @throws InvalidInputError if `name` has no value (a programming error in the caller).
  bool getBool(const std::string& name) const;
  int getInt(const std::string& name) const;
  double getFloat(const std::string& name) const;
  int getEnum(const std::string& name) const;

 private:
  double get(const std::string& name) const;
  std::map<std::string, double> values_;
};

}  // namespace elastica::app
