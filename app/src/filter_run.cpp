#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/hole_filling.h>
#include <elastica/mesh_curvature.h>
#include <elastica/topology.h>

#include <algorithm>
#include <cstdio>
#include <limits>

namespace elastica::app {
namespace {

std::string number(double x, const char* fmt = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

// The value of enum parameter `name`: its menu index (a script may carry any integer) looked up
// in the choices table, which is also where the menu's entries come from.
template <class E>
E enumValue(const ParamValues& v, const std::string& name) {
  const int i = v.getEnum(name);
  const std::vector<Choice<E>>& table = choices<E>();
  const int n = static_cast<int>(table.size());
  if (i < 0 || i >= n)
    throw InvalidInputError("parameter '" + name + "': enum value " + std::to_string(i) + " is not in 0.." +
                            std::to_string(n - 1));
  return table[static_cast<std::size_t>(i)].value;
}

Topology checkedTopology(const TriMesh& mesh, bool rejectNonManifoldVertices) {
  return checkedTopology(mesh, rejectNonManifoldVertices, RepairHints::MeshLab);
}

// The value of number parameter `name`, checked against the range its spec declares.
double checkedNumber(const ParamValues& v, const FilterSpec& spec, const std::string& name) {
  const ParamSpec& p = *spec.param(name);
  const double x = p.type == ParamType::Int ? double(v.getInt(name)) : v.getFloat(name);
  if (x >= p.minValue && x <= p.maxValue) return x;
  std::string range = p.maxValue < std::numeric_limits<double>::infinity()
                          ? "in " + number(p.minValue) + ".." + number(p.maxValue)
                          : ">= " + number(p.minValue);
  if (!p.rangeHint.empty()) range += " (" + p.rangeHint + ")";
  throw InvalidInputError("parameter '" + name + "' must be " + range);
}

// flow, scheme and maxSteps: the parameters every flow filter has.
void readFlowParameters(const ParamValues& v, const FilterSpec& spec, FlowOptions& o) {
  o.flow = enumValue<FlowType>(v, "flow");
  o.scheme = enumValue<Scheme>(v, "scheme");
  o.maxSteps = static_cast<long long>(checkedNumber(v, spec, "maxSteps"));
}

// MeshLab's progress from the flow's: the share of maxSteps taken.
std::function<bool(const FlowProgress&)> flowProgress(const Progress& progress, long long maxSteps) {
  if (!progress) return {};
  const double steps = double(std::max<long long>(maxSteps, 1));
  return [progress, steps](const FlowProgress& p) {
    const int percent = static_cast<int>(std::min(99.0, 100.0 * double(p.step) / steps));
    return progress(percent, "Elastica flow: level " + std::to_string(p.level) + ", step " + std::to_string(p.step) +
                                 ", energy " + number(p.energy));
  };
}

}  // namespace

Topology checkedTopology(const TriMesh& mesh, bool rejectNonManifoldVertices, RepairHints hints) {
  const bool meshlab = hints == RepairHints::MeshLab;
  if (mesh.faces.empty()) throw InvalidInputError("the mesh has no faces");
  Topology topo(mesh.vertexCount(), mesh.faces);
  if (topo.inconsistentEdgeCount() > 0)
    throw InvalidInputError("faces are not consistently oriented (" + std::to_string(topo.inconsistentEdgeCount()) +
                            " edges traversed the same way by both faces)" +
                            (meshlab ? "; re-orient them first: Filters > Normals > Re-Orient all faces coherently" : ""));
  const int nonManifold = rejectNonManifoldVertices ? topo.nonManifoldVertexCount() : 0;  // counted per call
  if (nonManifold > 0)
    throw InvalidInputError(std::to_string(nonManifold) + " non-manifold vertices (several fans of faces meet there)" +
                            (meshlab ? "; split them first: Filters > Cleaning and Repairing > Repair non Manifold "
                                       "Vertices by splitting"
                                     : ""));
  return topo;
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
  o.boundary = enumValue<BoundaryMode>(v, "boundary");
  o.subdivisionLevels = static_cast<int>(checkedNumber(v, spec, "subdivisionLevels"));
  o.energyTolerance = checkedNumber(v, spec, "energyTolerance");
  o.tangentialDrift = v.getBool("tangentialDrift");
  return o;
}

FairingResult runFairing(TriMesh mesh, std::vector<std::uint8_t> selection, const FlowOptions& opt,
                         bool outputCurvature) {
  const bool selected = !selection.empty();
  FairingResult r;
  const std::vector<Face> inputFaces = mesh.faces;
  const int inVertices = mesh.vertexCount();
  r.report = selected ? fair(mesh, FaceSet::fromFlags(selection), opt) : fair(mesh, opt);
  const FlowReport& report = r.report;
  if (report.stop == StopReason::Cancelled) throw Error("cancelled; the mesh is unchanged");

  r.connectivityChanged = mesh.faces != inputFaces;
  r.outputCurvature = outputCurvature;
  if (outputCurvature) r.curvature = measureCurvature(mesh, {opt.area, opt.curvature});
  r.log.push_back(std::to_string(inVertices) + " -> " + std::to_string(mesh.vertexCount()) + " vertices, " +
                  std::to_string(report.steps) + " steps in " + number(report.seconds, "%.2f") + " s (" +
                  labelOf(report.stop) + ")");
  r.log.push_back("total curvature energy " + number(report.energyInitial, "%.9g") + " -> " +
                  number(report.energyFinal, "%.9g"));
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
  opt.progress = flowProgress(progress, opt.maxSteps);
  if (!selected) selection.clear();
  return runFairing(std::move(mesh), std::move(selection), opt, v.getBool("colorByMeanCurvature"));
}

HoleFillOptions fillHolesOptions(const ParamValues& v) {
  const FilterSpec spec = filterSpec(FilterId::FillHoles, {});
  HoleFillOptions o;
  o.maxHoleEdges = static_cast<int>(checkedNumber(v, spec, "MaxHoleSize"));
  readFlowParameters(v, spec, o.flow);
  return o;
}

FillHolesResult runFillHoles(TriMesh mesh, const HoleFillOptions& opt, bool outputCurvature) {
  FillHolesResult r;
  r.originalVertices = mesh.vertexCount();
  r.originalFaces = mesh.faceCount();
  r.report = fillHoles(mesh, opt);
  r.outputCurvature = outputCurvature;
  if (outputCurvature) r.curvature = measureCurvature(mesh, {opt.flow.area, opt.flow.curvature});
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
  checkedTopology(mesh, /*rejectNonManifoldVertices=*/true);
  opt.flow.progress = flowProgress(progress, opt.flow.maxSteps);
  return runFillHoles(std::move(mesh), opt);
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
  opt.area = enumValue<VertexArea>(v, "area");
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
