// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/app/filter_spec.h>
#include <elastica/errors.h>

#include <cmath>
#include <cstdio>
#include <type_traits>

namespace elastica::app {
namespace {

const char* kReference =
    "<br><br>See: <i>S. Yoshizawa, A. G. Belyaev</i>, <b>\"Fair Triangle Mesh Generation with Discrete "
    "Elastica\"</b>, Geometric Modeling and Processing 2002, pp. 119-123.";

constexpr double kUnbounded = std::numeric_limits<double>::infinity();
// The dialogs' time limit: the default scheme converges on the 1,839-vertex bunny in seconds; a
// run that needs a minute is better stopped and reported than left to freeze MeshLab (which
// cannot cancel a running filter) or Blender.
constexpr float kDialogMaxSeconds = 60;

// ---- building rows ------------------------------------------------------------------------------
// `access` is a generic lambda returning the field of a JobOptions, const or not:
// [](auto& j) -> auto& { return j.flow.maxSteps; }.

struct Names {
  const char* mlx;      // "" where MeshLab has no such parameter
  const char* cli;
  const char* keyword;
  const char* blender;
};

ParamSpec blankRow(ParamType type, std::string field, Names n) {
  ParamSpec p;
  p.type = type;
  p.field = std::move(field);
  p.name = n.mlx;
  p.cliFlag = n.cli;
  p.keyword = n.keyword;
  p.blenderProperty = n.blender;
  return p;
}

template <class Access>
ParamSpec row(ParamType type, std::string field, Names n, Access access) {
  ParamSpec p = blankRow(type, std::move(field), n);
  p.set = [access](JobOptions& j, double x) {
    auto& f = access(j);
    f = static_cast<std::decay_t<decltype(f)>>(x);
  };
  p.get = [access](const JobOptions& j) { return static_cast<double>(access(j)); };
  p.defaultValue = p.get(JobOptions{});
  if (type == ParamType::Float && p.inMeshLab()) p.defaultValue = double(float(p.defaultValue));  // a RichFloat
  return p;
}

ParamSpec& help(ParamSpec& p, std::string label, std::string tooltip, std::string cliHelp = {}) {
  p.label = std::move(label);
  p.tooltip = std::move(tooltip);
  p.cliHelp = std::move(cliHelp);
  return p;
}

template <class Access>
ParamSpec boolRow(std::string field, Names n, Access access, std::string label, std::string tooltip,
                  std::string cliHelp = {}) {
  ParamSpec p = row(ParamType::Bool, std::move(field), n, access);
  return help(p, std::move(label), std::move(tooltip), std::move(cliHelp));
}

template <class Access>
ParamSpec numberRow(ParamType type, std::string field, Names n, Access access, double lo, double hi, std::string label,
                    std::string tooltip, std::string cliHelp = {}) {
  ParamSpec p = row(type, std::move(field), n, access);
  p.minValue = lo;
  p.maxValue = hi;
  return help(p, std::move(label), std::move(tooltip), std::move(cliHelp));
}

template <class E, class Access>
ParamSpec enumRow(std::string field, Names n, Access access, std::string label, std::string tooltip,
                  std::string cliHelp = {}) {
  ParamSpec p = blankRow(ParamType::Enum, std::move(field), n);
  for (const Choice<E>& c : choices<E>()) {
    p.enumValues.emplace_back(c.label);
    p.enumWords.emplace_back(c.name);
  }
  p.set = [access](JobOptions& j, double x) { access(j) = choices<E>()[static_cast<std::size_t>(x)].value; };
  p.get = [access](const JobOptions& j) { return double(indexOf(access(j))); };
  p.defaultValue = p.get(JobOptions{});
  p.minValue = 0;
  p.maxValue = double(choices<E>().size() - 1);
  return help(p, std::move(label), std::move(tooltip), std::move(cliHelp));
}

// ---- the rows every flow has (fairing: j.flow; fill: j.fill.flow) ------------------------------

template <class Flow>
std::vector<ParamSpec> flowRows(const std::string& prefix, Flow flow) {
  std::vector<ParamSpec> rows;
  rows.push_back(enumRow<FlowType>(
      prefix + "flow", {"flow", "--flow", "flow", "flow"}, [flow](auto& j) -> auto& { return flow(j).flow; }, "Flow",
      "Elastica: round (Willmore) surfaces. Laplacian of H: keeps the volume. Bilaplacian: shrinks.",
      "elastica (default: F = -Lap H - 2H(H^2-K)), lmc (F = -Lap H) or bilaplacian (P -= tau U0^2 P)"));
  rows.push_back(enumRow<Scheme>(
      prefix + "scheme", {"scheme", "--scheme", "scheme", "scheme"}, [flow](auto& j) -> auto& { return flow(j).scheme; },
      "Time integration",
      "Automatic: Vector, or Semi-implicit where Vector takes no first step. Explicit: the paper's tiny steps.",
      "auto (fair's default: vector, or semi-implicit where the vector scheme cannot take its first step), vector (implicit in the positions, adaptive steps that move vertices tangentially too, with "
      "remeshing), semi-implicit (fill's default: implicit in the 4th-order part, normal moves) or explicit "
      "(the paper's step; the bilaplacian flow's only scheme)"));
  // 0 is "no limit" on every face (the core's field takes the largest count instead).
  ParamSpec steps = numberRow(
      ParamType::Int, prefix + "maxSteps", {"maxSteps", "--max-steps", "max_steps", "max_steps"},
      [flow](auto& j) -> auto& { return flow(j).maxSteps; }, 0, kUnbounded, "Maximum steps",
      "Over all stages; 0: no limit (the flow stops at its plateau first).", "step limit over all stages (0: no limit)");
  steps.set = [flow](JobOptions& j, double x) { flow(j).maxSteps = stepLimit(static_cast<long long>(x)); };
  steps.get = [flow](const JobOptions& j) {
    const long long n = flow(j).maxSteps;
    return n == std::numeric_limits<long long>::max() ? 0.0 : double(n);
  };
  steps.defaultValue = steps.get(JobOptions{});  // the core's: no limit, 0 on every face
  rows.push_back(steps);
  ParamSpec seconds = numberRow(
      ParamType::Float, prefix + "maxSeconds", {"maxSeconds", "--max-seconds", "max_seconds", "max_seconds"},
      [flow](auto& j) -> auto& { return flow(j).maxSeconds; }, 0, kUnbounded, "Time limit (s)",
      "Then stop and keep the result, with a warning; 0: no limit. (MeshLab cannot cancel a running filter.)",
      "wall-time limit (0: none)");
  seconds.defaultValue = kDialogMaxSeconds;
  rows.push_back(seconds);
  return rows;
}

// The flow's tolerances and the explicit scheme's knobs, the CLI's only (and the fairing dialog's
// energy tolerance and tangential drift when `inDialog`).
template <class Flow>
std::vector<ParamSpec> flowTuningRows(const std::string& prefix, Flow flow, bool inDialog) {
  std::vector<ParamSpec> rows;
  rows.push_back(numberRow(
      ParamType::Float, prefix + "energyTolerance",
      {inDialog ? "energyTolerance" : "", "--energy-tol", inDialog ? "energy_tol" : "", inDialog ? "energy_tol" : ""},
      [flow](auto& j) -> auto& { return flow(j).energyTolerance; }, 0, kUnbounded, "Energy tolerance",
      "Stop when the energy's relative change per unit of normalised time is below this.",
      "stop when the relative energy change per unit of normalised time t/A^2 is below this"));
  rows.push_back(numberRow(
      ParamType::Float, prefix + "shapeTolerance", {"", "--shape-tol", "", ""},
      [flow](auto& j) -> auto& { return flow(j).shapeTolerance; }, 0, kUnbounded, "Shape tolerance",
      "Semi-implicit scheme: also stop once a step at the scale of the moving region moves no vertex along its "
      "normal by more than this times the mean edge length (0: off).",
      "semi-implicit scheme only: also stop once a step at the scale of the moving region moves no vertex along its "
      "normal by more than this times the mean edge length (fill's default 1e-3; fair's 0: off)"));
  rows.push_back(boolRow(
      prefix + "tangentialDrift",
      {inDialog ? "tangentialDrift" : "", "--no-tangential", inDialog ? "tangential" : "", inDialog ? "tangential" : ""},
      [flow](auto& j) -> auto& { return flow(j).tangentialDrift; }, "Tangential drift",
      "Explicit: the paper's drift each step. Semi-implicit: 2 passes a step. Vector: none.",
      "disable the tangential drift that keeps triangles even"));
  rows.push_back(enumRow<H2KTreatment>(
      prefix + "curvature.h2k", {"", "--h2k", "", ""}, [flow](auto& j) -> auto& { return flow(j).curvature.h2k; },
      "Where H^2 - K is below 0", "Clamp H^2 - K at 0, or the paper's lambda rescaling of H (guarded).",
      "H^2-K < 0: clamp (default) or lambda (the paper's rescaling, guarded)"));
  rows.push_back(enumRow<VertexArea>(
      prefix + "area", {"", "--area", "", ""}, [flow](auto& j) -> auto& { return flow(j).area; }, "Vertex area",
      "Mixed: Meyer et al.'s Voronoi area. Barycentric: the paper's A/3.",
      "vertex area: mixed (default) or barycentric (the paper's A/3)"));
  ParamSpec step = numberRow(ParamType::Float, prefix + "stepFactor", {"", "--step-factor", "", ""},
                             [flow](auto& j) -> auto& { return flow(j).stepFactor; }, 0, kUnbounded, "Step factor",
                             "Explicit scheme: the step is this times the smallest vertex area squared (paper: 1/150).",
                             "explicit step tau = factor * A_min^2 (paper: 1/150)");
  step.minExclusive = true;
  rows.push_back(step);
  return rows;
}

void append(std::vector<ParamSpec>& to, std::vector<ParamSpec> rows) {
  for (ParamSpec& p : rows) to.push_back(std::move(p));
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
  auto flow = [](auto& j) -> auto& { return j.flow; };
  std::vector<ParamSpec>& p = s.params;
  append(p, flowRows("flow.", flow));
  // Default "auto" on every face (fairing_amount.h): the dialogs show the length it stands for on
  // the mesh at hand (MeshFacts::featureSize), the CLI and Python leave it to runFairing.
  ParamSpec feature = numberRow(
      ParamType::AbsPerc, "flow.featureSize", {"featureSize", "--feature-size", "feature_size", "feature_size"},
      [](auto& j) -> auto& { return j.flow.featureSize; }, 0, kUnbounded, "Feature size",
      "Smooth away bumps smaller than this length, keep larger shapes. Default: the mesh's own, from its edge "
      "lengths and roughness. 0: fair to the limit shape (a sphere, a Clifford torus), which changes the whole model. "
      "-1 in a script: the default.",
      "a fairing amount, a length in the mesh's units (as the output prints it and the report's feature_size holds "
      "it): smooth away bumps smaller than it, keep larger shapes, then stop. Default auto: sized from the faces to "
      "fair, 2 short edge lengths (the 25 % quantile) on a clean surface and more on a noisy one (docs/options.md), "
      "halved while it would raise the energy; the output says when the result is still rough and suggests an "
      "amount. 0: fair until converged, to the limit shape (a sphere, a Clifford torus)");
  feature.defaultValue = mesh.featureSize;
  p.push_back(feature);
  p.push_back(numberRow(
      ParamType::Int, "flow.subdivisionLevels", {"subdivisionLevels", "--subdivide", "subdivide", "subdivide"},
      [](auto& j) -> auto& { return j.flow.subdivisionLevels; }, 0, 8, "Subdivision levels",
      "Coarse to fine: 1-to-4 splits, each near steady state (of the selection, if selected).",
      "coarse-to-fine: 1-to-4 subdivisions, each when the flow is near steady state (with a selection, of the "
      "selected faces only)"));
  p.push_back(numberRow(ParamType::Float, "flow.targetEdgeLength", {"", "--target-edge", "", ""},
                        [](auto& j) -> auto& { return j.flow.targetEdgeLength; }, 0, kUnbounded, "Target edge length",
                        "Stop subdividing once the mean edge length is at most this (0: no target).",
                        "stop subdividing once the mean edge length is at most this"));
  append(p, flowTuningRows("flow.", flow, /*inDialog=*/true));
  ParamSpec flips = boolRow("flow.flipEdges", {"", "--flip-edges", "flip_edges", ""},
                      [](auto& j) -> auto& { return j.flow.flipEdges; }, "Flip edges",
                      "Explicit scheme: dynamic connectivity, flip non-Delaunay edges among moving vertices at every check.",
                      "explicit scheme: dynamic connectivity, flip non-Delaunay edges among moving vertices at every "
                      "check (the vector and semi-implicit schemes do this and more unless --no-remesh)");
  flips.cliAlias = "--remesh";  // its first spelling, still taken
  p.push_back(flips);
  p.push_back(boolRow("flow.remesh", {"", "--no-remesh", "remesh", ""}, [](auto& j) -> auto& { return j.flow.remesh; },
                      "Remesh",
                      "Vector and semi-implicit schemes: the mesh-quality stages (working-resolution floor, "
                      "isotropic and curvature-adaptive remeshing, edge flips, embedding guard); off keeps the "
                      "connectivity.",
                      "vector and semi-implicit schemes: keep the connectivity (no working-resolution floor, no "
                      "isotropic or curvature-adaptive remeshing, no edge flips, no embedding guard)"));
  p.push_back(enumRow<BoundaryMode>(
      "flow.boundary", {"boundary", "--boundary", "boundary", "boundary"}, [](auto& j) -> auto& { return j.flow.boundary; },
      "Boundary", "Fixed: the boundary and the next ring stay put (G1). Slide: the boundary slides along itself.",
      "fixed (default: boundary and next row clamped, G1) or slide (boundary vertices slide along it)"));
  ParamSpec selected = boolRow(
      "selected", {"Selected", "--selected", "", ""}, [](auto& j) -> auto& { return j.selected; },
      "Affect only selected faces", "Only vertices whose faces are all selected move; two rings around them stay fixed.",
      "fair only the selected faces (PLY face flags, as MeshLab saves its selection, or a face property 'selected'); "
      "two rings around stay fixed");
  selected.defaultValue = mesh.selectedFaces > 0;  // MeshLab's idiom: on when the mesh has a selection
  p.push_back(selected);
  p.push_back(boolRow("colorByMeanCurvature",
                      {"colorByMeanCurvature", "--color-by-mean-curvature", "", "color_by_mean_curvature"},
                      [](auto& j) -> auto& { return j.colorByMeanCurvature; }, "Colour by mean curvature",
                      "Store H (+1/r on a sphere) as vertex quality; colour by it (red low, blue high).",
                      "colour vertices by H (red low, blue high)"));
  return s;
}

FilterSpec fillHoles() {
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
  std::vector<ParamSpec>& p = s.params;
  ParamSpec size = numberRow(
      ParamType::Int, "fill.maxHoleEdges", {"MaxHoleSize", "--max-hole-edges", "max_hole_edges", "max_hole_edges"},
      [](auto& j) -> auto& { return j.fill.maxHoleEdges; }, 3, kUnbounded, "Max size to be closed",
      "Holes with more border edges than this stay open (counted as in MeshLab's Close Holes).",
      "fill holes with at most this many border edges");
  size.rangeHint = "a hole has 3 edges or more";
  p.push_back(size);
  p.push_back(boolRow("fill.closeRims", {"CloseRims", "--close-rims", "close_rims", "close_rims"},
                      [](auto& j) -> auto& { return j.fill.closeRims; }, "Close rims too",
                      "Off: the outer rim of an open surface (a scan's outline: a border that turns like an outline "
                      "and spans a quarter or more of its piece's area) stays open and only the holes inside are "
                      "filled. On: rims are closed too.",
                      "also close the outer rims of open surfaces (by default a scan's outline stays open: a border "
                      "that turns like an outline and spans a quarter or more of its piece's area; "
                      "docs/restoration.md)"));
  p.push_back(enumRow<FillStage>("fill.stopAfter", {"", "--stop-after", "", ""},
                                 [](auto& j) -> auto& { return j.fill.stopAfter; }, "Stop after",
                                 "The last stage of each hole's pipeline (the others are comparisons).",
                                 "triangulation, refinement, biharmonic (CGAL-like fairing) or flow (default)"));
  ParamSpec density = numberRow(ParamType::Float, "fill.refinement.density", {"", "--density", "", ""},
                                [](auto& j) -> auto& { return j.fill.refinement.density; }, 0, kUnbounded,
                                "Refinement density", "Liepa's refinement factor: larger makes smaller triangles.",
                                "Liepa's refinement factor: larger makes smaller triangles");
  density.minExclusive = true;
  p.push_back(density);
  auto flow = [](auto& j) -> auto& { return j.fill.flow; };
  append(p, flowRows("fill.flow.", flow));
  append(p, flowTuningRows("fill.flow.", flow, /*inDialog=*/false));
  p.push_back(boolRow("selectNewFaces", {"NewFaceSelected", "", "", "select_new_faces"},
                      [](auto& j) -> auto& { return j.selectNewFaces; }, "Select the newly created faces",
                      "Afterwards only the new faces are selected (with no hole filled, the selection stays)."));
  p.push_back(boolRow("colorByMeanCurvature", {"", "--color-by-mean-curvature", "", ""},
                      [](auto& j) -> auto& { return j.colorByMeanCurvature; }, "Colour by mean curvature",
                      "Store H (+1/r on a sphere) as vertex quality; colour by it (red low, blue high).",
                      "colour vertices by H (red low, blue high)"));
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
  // The paper's lambda fix, as a switch: the one place a bool becomes the H2KTreatment.
  ParamSpec lambda = blankRow(ParamType::Bool, "curvature.curvature.h2k",
                              {"lambdaFix", "--lambda-fix", "lambda_fix", "lambda_fix"});
  help(lambda, "Paper's lambda fix",
       "Where H² is below K (common on meshes), rescale H by the paper's lambda (at least 0.5).",
       "apply the paper's lambda rescaling of H where H^2 < K (guarded); E still uses raw H");
  lambda.set = [](JobOptions& j, double x) {
    j.curvature.curvature.h2k = x != 0 ? H2KTreatment::PaperLambda : H2KTreatment::Clamp;
  };
  lambda.get = [](const JobOptions& j) { return j.curvature.curvature.h2k == H2KTreatment::PaperLambda ? 1.0 : 0.0; };
  lambda.defaultValue = lambda.get(JobOptions{});
  s.params = {
      lambda,
      enumRow<VertexArea>(
          "curvature.area", {"area", "--area", "area", "area"}, [](auto& j) -> auto& { return j.curvature.area; },
          "Vertex area",
          "Mixed: Meyer et al.'s Voronoi area (converges). Barycentric: the paper's A/3 (H up to 15 % off).",
          "vertex area: mixed (Meyer et al.'s mixed Voronoi area, default) or barycentric (the paper's A/3)"),
  };
  return s;
}

// A value or bound in a range error, to 9 digits (filter_run.cpp's number() has a format argument).
std::string boundText(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
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

std::string ParamSpec::describe(Caller face) const {
  switch (face) {
    case Caller::MeshLab:
      if (inMeshLab()) return "'" + label + "' (" + name + ")";
      break;
    case Caller::Cli:
      if (!cliFlag.empty()) return cliFlag;
      break;
    case Caller::Python:
      if (!keyword.empty()) return keyword;
      break;
    case Caller::Blender:
      if (!blenderProperty.empty()) return "'" + label + "' (" + blenderProperty + ")";
      break;
    case Caller::Api: break;
  }
  return field;
}

const ParamSpec* FilterSpec::param(const std::string& n) const {
  for (const ParamSpec& p : params)
    if (p.inMeshLab() && p.name == n) return &p;
  return nullptr;
}

const ParamSpec* FilterSpec::row(const std::string& key) const {
  for (const ParamSpec& p : params)
    if (p.key() == key) return &p;
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
  for (const ParamSpec& p : spec.params)
    if (p.inMeshLab()) v.set(p.key(), p.defaultValue);
  return v;
}

double ParamValues::get(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end()) throw InvalidInputError("parameter '" + key + "' has no value");
  return it->second;
}
bool ParamValues::getBool(const std::string& key) const { return get(key) != 0; }
int ParamValues::getInt(const std::string& key) const { return static_cast<int>(get(key)); }
double ParamValues::getFloat(const std::string& key) const { return get(key); }
int ParamValues::getEnum(const std::string& key) const { return static_cast<int>(get(key)); }

void checkValue(const ParamSpec& p, double x, Caller face) {
  if (p.type == ParamType::Bool) return;
  if (p.type == ParamType::Enum) {
    const int n = static_cast<int>(p.enumValues.size());
    if (x == std::floor(x) && x >= 0 && x < n) return;
    throw InvalidInputError(p.describe(face) + ": enum value " + boundText(x) + " is not in 0.." + std::to_string(n - 1));
  }
  if (p.type == ParamType::AbsPerc && x == kAutoFeatureSize) return;  // "auto", every face's default
  const double lo = p.minValue, hi = p.maxValue;
  if ((p.minExclusive ? x > lo : x >= lo) && x <= hi) return;  // NaN fails both
  std::string range =
      hi < kUnbounded ? "in " + boundText(lo) + ".." + boundText(hi) : (p.minExclusive ? "> " : ">= ") + boundText(lo);
  if (p.type == ParamType::AbsPerc) range += " (a length in the mesh's units; -1: auto)";
  if (!p.rangeHint.empty()) range += " (" + p.rangeHint + ")";
  throw InvalidInputError(p.describe(face) + " must be " + range + ", not " + boundText(x));
}

JobOptions readJob(const FilterSpec& spec, const ParamValues& v, Caller face) {
  JobOptions job;
  for (const ParamSpec& p : spec.params) {
    if (!v.has(p.key())) continue;
    const double x = v.getFloat(p.key());
    checkValue(p, x, face);
    p.set(job, x);
  }
  return job;
}

void checkOptions(FilterId id, const JobOptions& job) {
  for (const ParamSpec& p : filterSpec(id, {}).params) checkValue(p, p.get(job), Caller::Api);
}

}  // namespace elastica::app
