#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/hole_filling.h>
#include <elastica/mesh_curvature.h>
#include <elastica/topology.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace elastica::app {
namespace {

std::string number(double x, const char* fmt = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

// A parameter as the user sees it: the dialog's label, then the .mlx name ('Maximum steps'
// (maxSteps)), so a message reads right in MeshLab's dialog and next to a script alike.
std::string describe(const ParamSpec& p) { return "'" + p.label + "' (" + p.name + ")"; }

// The value of enum parameter `name`: its menu index (a script may carry any integer) looked up
// in the choices table, which is also where the menu's entries come from.
template <class E>
E enumValue(const ParamValues& v, const FilterSpec& spec, const std::string& name) {
  const int i = v.getEnum(name);
  const std::vector<Choice<E>>& table = choices<E>();
  const int n = static_cast<int>(table.size());
  if (i < 0 || i >= n)
    throw InvalidInputError(describe(*spec.param(name)) + ": enum value " + std::to_string(i) + " is not in 0.." +
                            std::to_string(n - 1));
  return table[static_cast<std::size_t>(i)].value;
}

Topology checkedTopology(const TriMesh& mesh, bool rejectNonManifoldVertices) {
  return checkedTopology(mesh, rejectNonManifoldVertices, RepairHints::MeshLab);
}

// The value of number parameter `name`, checked against the range its spec declares.
double checkedNumber(const ParamValues& v, const FilterSpec& spec, const std::string& name) {
  const ParamSpec& p = *spec.param(name);
  const double x = p.type == ParamType::Int ? double(v.getInt(name)) : v.getFloat(name);  // Float, AbsPerc
  if (x >= p.minValue && x <= p.maxValue) return x;
  std::string range = p.maxValue < std::numeric_limits<double>::infinity()
                          ? "in " + number(p.minValue) + ".." + number(p.maxValue)
                          : ">= " + number(p.minValue);
  if (!p.rangeHint.empty()) range += " (" + p.rangeHint + ")";
  throw InvalidInputError(describe(p) + " must be " + range);
}

// flow, scheme, maxSteps and maxSeconds: the parameters every flow filter has. (maxSeconds came
// later; a caller's values without it keep the core's "no limit".)
void readFlowParameters(const ParamValues& v, const FilterSpec& spec, FlowOptions& o) {
  o.flow = enumValue<FlowType>(v, spec, "flow");
  o.scheme = enumValue<Scheme>(v, spec, "scheme");
  o.maxSteps = stepLimit(static_cast<long long>(checkedNumber(v, spec, "maxSteps")));
  if (v.has("maxSeconds")) o.maxSeconds = checkedNumber(v, spec, "maxSeconds");
}

}  // namespace

long long stepLimit(long long steps) { return steps == 0 ? std::numeric_limits<long long>::max() : steps; }

std::function<bool(const FlowProgress&)> flowProgress(const Progress& progress, const FlowOptions& o) {
  if (!progress) return {};
  const auto start = std::chrono::steady_clock::now();
  auto shown = std::make_shared<double>(0.0);  // the fraction shown last: progress never goes back
  const double stages = double(std::max(o.subdivisionLevels, 0) + 1);
  const double maxSeconds = o.maxSeconds;
  const double maxSteps = double(o.maxSteps);
  return [progress, start, shown, stages, maxSeconds, maxSteps](const FlowProgress& p) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double f = double(p.level) / stages;
    if (maxSeconds > 0) f = std::max(f, seconds / maxSeconds);
    if (maxSteps > 0 && maxSteps < 1e18) f = std::max(f, double(p.step) / maxSteps);
    f = std::min(0.99, std::max(f, *shown));
    *shown = f;
    std::string what = "Elastica flow: level " + std::to_string(p.level) + ", step " + std::to_string(p.step) +
                       ", energy " + number(p.energy) + ", " + number(seconds, "%.0f") + " s";
    if (maxSeconds > 0) what += " of at most " + number(maxSeconds, "%.0f") + " s";
    return progress(static_cast<int>(100.0 * f), what);
  };
}

namespace {

// The warning for a flow that ended at one of its limits, naming the dialog field to change ("" if
// it converged or stalled).
std::string limitWarning(StopReason stop, const FilterSpec& spec, const FlowOptions& o) {
  if (stop == StopReason::MaxSeconds)
    return "warning: stopped at the time limit of " + number(o.maxSeconds) +
           " s before the flow converged; the mesh is the state reached then. To let it run longer raise " +
           describe(*spec.param("maxSeconds")) + " (0: no limit)" +
           (o.scheme == Scheme::Explicit ? ", or choose the Semi-implicit 'Time integration', which needs far "
                                           "fewer steps"
                                         : "");
  if (stop == StopReason::MaxSteps)
    return "warning: stopped after " + std::to_string(o.maxSteps) +
           " steps before the flow converged; the mesh is the state reached then. To let it run longer raise " +
           describe(*spec.param("maxSteps")) +
           (o.scheme == Scheme::Explicit ? ", or choose the Semi-implicit 'Time integration', which needs far "
                                           "fewer steps"
                                         : "");
  return {};
}

}  // namespace

namespace {

// What every job refuses, with the words of `hints`.
void rejectDefects(int inconsistentEdges, int nonManifoldVertices, RepairHints hints) {
  const bool meshlab = hints == RepairHints::MeshLab;
  if (inconsistentEdges > 0)
    throw InvalidInputError("faces are not consistently oriented (" + std::to_string(inconsistentEdges) +
                            " edges traversed the same way by both faces)" +
                            (meshlab ? "; re-orient them first: Filters > Normals > Re-Orient all faces coherently" : ""));
  if (nonManifoldVertices > 0)
    throw InvalidInputError(std::to_string(nonManifoldVertices) + " non-manifold vertices (several fans of faces meet there)" +
                            (meshlab ? "; split them first: Filters > Cleaning and Repairing > Repair non Manifold "
                                       "Vertices by splitting"
                                     : ""));
}

}  // namespace

Topology checkedTopology(const TriMesh& mesh, bool rejectNonManifoldVertices, RepairHints hints) {
  if (mesh.faces.empty()) throw InvalidInputError("the mesh has no faces");
  Topology topo(mesh.vertexCount(), mesh.faces);
  rejectDefects(topo.inconsistentEdgeCount(), rejectNonManifoldVertices ? topo.nonManifoldVertexCount() : 0, hints);
  return topo;
}

void checkFillInput(const TriMesh& mesh, RepairHints hints) {
  if (mesh.faces.empty()) throw InvalidInputError("the mesh has no faces");
  const FillInputDefects d = countFillInputDefects(mesh);
  rejectDefects(d.inconsistentEdges, d.nonManifoldVertices, hints);
}

FilterOutputs filterOutputs(FilterId id, const ParamValues& v) {
  switch (id) {
    case FilterId::Fairing: return {v.getBool("colorByMeanCurvature"), v.getBool("Selected")};
    case FilterId::FillHoles: return {false, v.getBool("NewFaceSelected")};
    case FilterId::Curvature: return {true, false};
  }
  return {};
}

FlowOptions fairingOptions(const ParamValues& v) {
  const FilterSpec spec = filterSpec(FilterId::Fairing, {});
  FlowOptions o;
  readFlowParameters(v, spec, o);
  o.boundary = enumValue<BoundaryMode>(v, spec, "boundary");
  o.subdivisionLevels = static_cast<int>(checkedNumber(v, spec, "subdivisionLevels"));
  o.energyTolerance = checkedNumber(v, spec, "energyTolerance");
  o.tangentialDrift = v.getBool("tangentialDrift");
  if (v.has("featureSize")) o.featureSize = checkedNumber(v, spec, "featureSize");  // a length
  return o;
}

FairingResult runFairing(TriMesh mesh, std::vector<std::uint8_t> selection, const FlowOptions& opt,
                         bool outputCurvature) {
  const bool selected = !selection.empty();
  FairingResult r;
  const std::vector<Face> inputFaces = mesh.faces;
  const int inVertices = mesh.vertexCount();
  const CurvatureMeasureOptions measure{opt.area, opt.curvature};
  r.energyInput = measureCurvature(mesh, measure).energy;
  r.report = selected ? fair(mesh, FaceSet::fromFlags(selection), opt) : fair(mesh, opt);
  const FlowReport& report = r.report;
  if (report.stop == StopReason::Cancelled) throw Error("cancelled; the mesh is unchanged");

  r.connectivityChanged = mesh.faces != inputFaces;
  r.outputCurvature = outputCurvature;
  if (outputCurvature) r.curvature = measureCurvature(mesh, measure);
  r.energyOutput = outputCurvature ? r.curvature.energy : measureCurvature(mesh, measure).energy;
  r.log.push_back(std::to_string(inVertices) + " -> " + std::to_string(mesh.vertexCount()) + " vertices, " +
                  std::to_string(report.steps) + " steps in " + number(report.seconds, "%.2f") + " s (" +
                  labelOf(report.stop) + ")");
  r.log.push_back("total curvature energy " + number(r.energyInput, "%.9g") + " -> " + number(r.energyOutput, "%.9g"));
  // The flow's own start differs when it refined or remeshed the mesh first, or faired a region.
  if (std::abs(report.energyInitial - r.energyInput) > 1e-9 * std::abs(r.energyInput))
    r.log.push_back(std::string("the flow's energy, ") + (selected ? "over the region that moves" : "on its working mesh") +
                    (report.preSubdivisions + report.remeshings > 0 ? " after refinement or remeshing" : "") + ": " +
                    number(report.energyInitial, "%.9g") + " -> " + number(report.energyFinal, "%.9g"));
  r.mesh = std::move(mesh);
  if (selected) r.selection = FaceSet(report.regionFaces).flags(r.mesh.faces.size());
  return r;
}

FairingResult runFairing(TriMesh mesh, std::vector<std::uint8_t> selection, const ParamValues& v,
                         const Progress& progress) {
  FlowOptions opt = fairingOptions(v);
  const bool selected = v.getBool("Selected");
  checkedTopology(mesh, /*rejectNonManifoldVertices=*/true);
  if (selected && std::count(selection.begin(), selection.end(), 1) == 0)
    throw InvalidInputError("'Affect only selected faces' is on, but no face is selected");
  opt.progress = flowProgress(progress, opt);
  if (!selected) selection.clear();
  FairingResult r = runFairing(std::move(mesh), std::move(selection), opt, v.getBool("colorByMeanCurvature"));
  const std::string warning = limitWarning(r.report.stop, filterSpec(FilterId::Fairing, {}), opt);
  if (!warning.empty()) r.log.push_back(warning);
  const int levels = r.report.stages.empty() ? 0 : r.report.stages.back().level;
  if (selected && levels > 0)
    r.log.push_back("only the selected faces were subdivided (" + std::to_string(levels) +
                    (levels == 1 ? " level" : " levels") +
                    "; the faces along the selection were split to keep the mesh conforming); only they moved, "
                    "and they are selected in the refined mesh");
  return r;
}

HoleFillOptions fillHolesOptions(const ParamValues& v) {
  const FilterSpec spec = filterSpec(FilterId::FillHoles, {});
  HoleFillOptions o;
  o.maxHoleEdges = static_cast<int>(checkedNumber(v, spec, "MaxHoleSize"));
  o.closeRims = v.getBool("CloseRims");
  readFlowParameters(v, spec, o.flow);
  return o;
}

FillHolesResult runFillHoles(TriMesh mesh, const HoleFillOptions& opt, bool outputCurvature) {
  FillHolesResult r;
  r.originalVertices = mesh.vertexCount();
  r.originalFaces = mesh.faceCount();
  r.report = fillHoles(mesh, opt);
  r.outputCurvature = outputCurvature;
  // In pieces: the whole output's Topology, Geometry and Curvature would be the run's peak (1.1 GB
  // beside a 2.2-million-vertex scan, for `elastica fill`).
  if (outputCurvature) r.curvature = measureCurvatureInPieces(mesh, {opt.flow.area, opt.flow.curvature});
  const HoleFillReport& report = r.report;
  for (const HoleReport& h : report.holes) {
    std::string line = "hole of " + std::to_string(h.borderEdges) + " border edges: ";
    if (h.filled)
      line += "filled with " + std::to_string(h.newVertices) + " vertices and " + std::to_string(h.newFaces) +
              " faces; patch energy " + number(h.energyBefore) + " -> " + number(h.energyAfter) + " in " +
              std::to_string(h.steps) + " steps (" + labelOf(h.stop) + ")";
    else
      line += "left open";
    if (!h.reason.empty()) line += "; " + h.reason;
    r.log.push_back(line);
  }
  if (!report.welds.empty())
    r.log.push_back("merged " + std::to_string(report.welds.size()) +
                    " pairs of vertex copies at one point where a patch joined their fans");
  r.log.push_back("filled " + std::to_string(report.filledCount()) + " of " + std::to_string(report.holes.size()) +
                  " holes in " + number(report.seconds, "%.2f") + " s");
  r.mesh = std::move(mesh);
  return r;
}

FillHolesResult runFillHoles(TriMesh mesh, const ParamValues& v, const Progress& progress) {
  HoleFillOptions opt = fillHolesOptions(v);
  checkFillInput(mesh, RepairHints::MeshLab);
  opt.flow.progress = flowProgress(progress, opt.flow);
  FillHolesResult r = runFillHoles(std::move(mesh), opt);
  const FilterSpec spec = filterSpec(FilterId::FillHoles, {});
  std::string warning;
  for (const HoleReport& h : r.report.holes)
    if (warning.empty() && h.filled) warning = limitWarning(h.stop, spec, opt.flow);
  if (!warning.empty()) r.log.push_back(warning);
  if (r.report.holes.empty())
    r.log = {"the mesh has no holes: nothing to fill; the mesh and its selection are unchanged"};
  else if (r.report.filledCount() == 0)
    r.log.push_back("no hole was filled: the mesh and its selection are unchanged");
  return r;
}

CurvatureResult runCurvature(const TriMesh& mesh, const CurvatureMeasureOptions& opt) {
  CurvatureResult r;
  r.curvature = measureCurvature(mesh, opt);
  r.lambdaFix = opt.curvature.h2k == H2KTreatment::PaperLambda;
  const MeshCurvature& c = r.curvature;
  auto [lo, hi] = std::minmax_element(c.H.begin(), c.H.end());
  // + 0.0 turns a negative zero into 0 for printing.
  if (!c.H.empty())
    r.log.push_back("mean curvature H (+1/r on a sphere): " + number(*lo + 0.0) + " .. " + number(*hi + 0.0));
  if (r.lambdaFix)
    r.log.push_back("paper's lambda fix: lambda = " + number(c.lambda) + " on " + std::to_string(c.lambdaVertices) +
                    " vertices (H written is H/lambda there)");
  const DegeneracyCounts& d = c.degenerate;
  if (d.total() > 0)
    r.log.push_back("degenerate, given zero weight: " + std::to_string(d.zeroAreaFaces) + " zero-area faces, " +
                    std::to_string(d.zeroLengthEdges) + " zero-length edges, " + std::to_string(d.zeroAreaVertices) +
                    " vertices without area, " + std::to_string(d.isolatedVertices) + " isolated vertices");
  r.log.push_back("total curvature energy E = " + number(c.energy, "%.9g"));
  return r;
}

CurvatureResult runCurvature(const TriMesh& mesh, const ParamValues& v) {
  CurvatureMeasureOptions opt;
  opt.area = enumValue<VertexArea>(v, filterSpec(FilterId::Curvature, {}), "area");
  opt.curvature.h2k = v.getBool("lambdaFix") ? H2KTreatment::PaperLambda : H2KTreatment::Clamp;
  const Topology topo = checkedTopology(mesh, /*rejectNonManifoldVertices=*/false);
  const int nonManifold = topo.nonManifoldVertexCount();  // counted per call
  CurvatureResult r = runCurvature(mesh, opt);
  if (nonManifold > 0)
    r.log.insert(r.log.begin(), "warning: " + std::to_string(nonManifold) +
                                    " non-manifold vertices; curvature there is not meaningful");
  return r;
}

}  // namespace elastica::app
