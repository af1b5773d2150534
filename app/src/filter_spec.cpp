#include <elastica/app/choices.h>
#include <elastica/app/filter_spec.h>
#include <elastica/errors.h>
#include <elastica/flow.h>
#include <elastica/hole_filling.h>

namespace elastica::app {
namespace {

const char* kReference =
    "<br><br>See: <i>S. Yoshizawa, A. G. Belyaev</i>, <b>\"Fair Triangle Mesh Generation with Discrete "
    "Elastica\"</b>, Geometric Modeling and Processing 2002, pp. 119-123.";

ParamSpec param(std::string name, ParamType type, double value, std::string label, std::string tooltip) {
  ParamSpec p;
  p.name = std::move(name);
  p.type = type;
  p.defaultValue = value;
  p.label = std::move(label);
  p.tooltip = std::move(tooltip);
  return p;
}
ParamSpec boolParam(std::string name, bool value, std::string label, std::string tooltip) {
  return param(std::move(name), ParamType::Bool, value ? 1.0 : 0.0, std::move(label), std::move(tooltip));
}
ParamSpec intParam(std::string name, int value, std::string label, std::string tooltip, double lo, double hi,
                   std::string hint = {}) {
  ParamSpec p = param(std::move(name), ParamType::Int, double(value), std::move(label), std::move(tooltip));
  p.minValue = lo;
  p.maxValue = hi;
  p.rangeHint = std::move(hint);
  return p;
}
ParamSpec floatParam(std::string name, float value, std::string label, std::string tooltip, double lo) {
  ParamSpec p = param(std::move(name), ParamType::Float, double(value), std::move(label), std::move(tooltip));
  p.minValue = lo;
  return p;
}
constexpr double kUnbounded = std::numeric_limits<double>::infinity();
// The time limit's default: the default scheme converges on the 1,839-vertex bunny in
// seconds; a run that needs a minute is better stopped and reported than left to freeze MeshLab.
constexpr float kDefaultMaxSeconds = 60;
ParamSpec absPercParam(std::string name, double fraction, double diagonal, std::string label, std::string tooltip) {
  ParamSpec p = param(std::move(name), ParamType::AbsPerc, fraction * diagonal, std::move(label), std::move(tooltip));
  p.minValue = 0;
  return p;
}
ParamSpec enumParam(std::string name, int value, std::vector<std::string> values, std::string label,
                    std::string tooltip) {
  ParamSpec p = param(std::move(name), ParamType::Enum, double(value), std::move(label), std::move(tooltip));
  p.enumValues = std::move(values);
  return p;
}

// The flow and scheme choices, shared by every filter that runs a flow (index order is the .mlx
// value: append only).
ParamSpec flowParam() {
  return enumParam("flow", 0, labels<FlowType>(), "Flow",
                   "Elastica: round (Willmore) surfaces. Laplacian of H: keeps the volume. Bilaplacian: shrinks.");
}
ParamSpec schemeParam(Scheme defaultScheme) {
  return enumParam("scheme", indexOf(defaultScheme), labels<Scheme>(), "Time integration",
                   "Automatic: Vector, or Semi-implicit on coarse meshes with handles. Explicit: the paper's tiny "
                   "steps.");
}
ParamSpec maxStepsParam() {
  return intParam("maxSteps", 0, "Maximum steps",
                  "Over all stages; 0: no limit (the flow stops at its plateau first).",
                  0, kUnbounded);
}
// The wall-time limit: MeshLab 2020.09 cannot cancel a running filter (its progress callback
// always answers "go on"), so this bounds how long a run keeps MeshLab busy.
ParamSpec maxSecondsParam() {
  return floatParam("maxSeconds", kDefaultMaxSeconds, "Time limit (s)",
                    "Then stop and keep the result, with a warning; 0: no limit. (MeshLab cannot cancel a "
                    "running filter.)",
                    0);
}

FilterSpec fairing(const MeshFacts& mesh) {
  FilterSpec s;
  s.id = FilterId::Fairing;
  s.name = "Discrete Elastica Fairing";
  s.info = std::string(
               "Fairs the mesh with the discrete elastica flow, the gradient descent of the total curvature "
               "&int;(k<sub>1</sub><sup>2</sup> + k<sub>2</sub><sup>2</sup>) dA (normal speed "
               "F = -&Delta;<sub>B</sub>H - 2H(H<sup>2</sup> - K)), toward round, fair surfaces.") +
           kReference;
  s.params = {
      flowParam(),
      schemeParam(FlowOptions{}.scheme),
      maxStepsParam(),
      maxSecondsParam(),
      absPercParam("featureSize", 0, mesh.diagonal, "Feature size",
                   "Smooth away bumps smaller than this, keep larger shapes. 0: fair until converged."),
      intParam("subdivisionLevels", 0, "Subdivision levels",
               "Coarse to fine: 1-to-4 splits, each near steady state (of the selection, if selected).",
               0, 8),
      floatParam("energyTolerance", float(FlowOptions{}.energyTolerance), "Energy tolerance",
                 "Stop when the energy's relative change per unit of normalised time is below this.",
                 0),
      boolParam("tangentialDrift", true, "Tangential drift",
                "Explicit: the paper's drift each step. Semi-implicit: 2 passes a step. Vector: none."),
      enumParam("boundary", indexOf(FlowOptions{}.boundary), labels<BoundaryMode>(), "Boundary",
                "Fixed: the boundary and the next ring stay put (G1). Slide: the boundary slides along itself."),
      boolParam("Selected", mesh.selectedFaces > 0, "Affect only selected faces",
                "Only vertices whose faces are all selected move; two rings around them stay fixed."),
      boolParam("colorByMeanCurvature", false, "Colour by mean curvature",
                "Store H (+1/r on a sphere) as vertex quality; colour by it (red low, blue high)."),
  };
  return s;
}

FilterSpec fillHoles() {
  const HoleFillOptions defaults;
  FilterSpec s;
  s.id = FilterId::FillHoles;
  s.name = "Fill Holes with Discrete Elastica";
  s.info = std::string(
               "Restores missing regions (the paper's shape restoration): every hole up to the given size is "
               "closed by a minimum-weight triangulation, refined to the density around it and started from a "
               "bi-Laplace solve. The patch is then faired with the discrete elastica flow (the gradient descent "
               "of the total curvature) while two rings of the surrounding mesh stay fixed, so that it joins "
               "with continuous tangent planes (G1) and continues the surface's curvature.") +
           kReference;
  s.params = {
      intParam("MaxHoleSize", defaults.maxHoleEdges, "Max size to be closed",
               "Holes with more border edges than this stay open (counted as in MeshLab's Close Holes).",
               3, kUnbounded, "a hole has 3 edges or more"),
      boolParam("CloseRims", defaults.closeRims, "Close rims too",
                "Off: the outer rim of an open surface (a scan's outline: a border that turns like an outline and "
                "spans a quarter or more of its piece's area) stays open and only the holes inside are filled. "
                "On: rims are closed too."),
      flowParam(),
      schemeParam(defaults.flow.scheme),
      maxStepsParam(),
      maxSecondsParam(),
      boolParam("NewFaceSelected", true, "Select the newly created faces",
                "Afterwards only the new faces are selected (with no hole filled, the selection stays)."),
  };
  return s;
}

FilterSpec curvature() {
  FilterSpec s;
  s.id = FilterId::Curvature;
  s.name = "Discrete Elastica Curvature";
  s.info = std::string(
               "Computes the discrete curvatures the elastica flow uses: the mean curvature H from the "
               "cotangent Laplace-Beltrami operator (&Delta;<sub>B</sub>P = 2HN, so H = +1/r on a sphere) "
               "and the Gaussian curvature K from the angle deficit (2&pi; - &Sigma;&phi;)/A. H goes into "
               "the vertex quality and colour (red low, blue high, over the 2-98 % range), and both H and K "
               "into the per-vertex attributes mean_curvature and gaussian_curvature.") +
           kReference;
  s.params = {
      boolParam("lambdaFix", false, "Paper's lambda fix",
                "Where H² is below K (common on meshes), rescale H by the paper's lambda (at least 0.5)."),
      enumParam("area", indexOf(VertexArea::Mixed), labels<VertexArea>(), "Vertex area",
                "Mixed: Meyer et al.'s Voronoi area (converges). Barycentric: the paper's A/3 (H up to 15 % off)."),
  };
  return s;
}

}  // namespace

const char* richTypeName(ParamType t) {
  switch (t) {
    case ParamType::Bool: return "RichBool";
    case ParamType::Int: return "RichInt";
    case ParamType::Float: return "RichFloat";
    case ParamType::Enum: return "RichEnum";
    case ParamType::AbsPerc: return "RichAbsPerc";
  }
  return "?";
}

const ParamSpec* FilterSpec::param(const std::string& n) const {
  for (const ParamSpec& p : params)
    if (p.name == n) return &p;
  return nullptr;
}

std::vector<FilterSpec> allFilters(const MeshFacts& mesh) { return {fairing(mesh), fillHoles(), curvature()}; }

FilterSpec filterSpec(FilterId id, const MeshFacts& mesh) {
  switch (id) {
    case FilterId::Fairing: return fairing(mesh);
    case FilterId::FillHoles: return fillHoles();
    case FilterId::Curvature: return curvature();
  }
  throw InvalidInputError("filterSpec: unknown filter id " + std::to_string(int(id)));
}

std::optional<FilterId> findFilter(const std::string& name) {
  for (const FilterSpec& s : allFilters({}))
    if (s.name == name) return s.id;
  return std::nullopt;
}

ParamValues ParamValues::defaults(const FilterSpec& spec) {
  ParamValues v;
  for (const ParamSpec& p : spec.params) v.set(p.name, p.defaultValue);
  return v;
}

double ParamValues::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) throw InvalidInputError("parameter '" + name + "' has no value");
  return it->second;
}
bool ParamValues::getBool(const std::string& name) const { return get(name) != 0; }
int ParamValues::getInt(const std::string& name) const { return static_cast<int>(get(name)); }
double ParamValues::getFloat(const std::string& name) const { return get(name); }
int ParamValues::getEnum(const std::string& name) const { return static_cast<int>(get(name)); }

}  // namespace elastica::app
