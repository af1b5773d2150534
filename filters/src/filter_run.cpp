#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/filters/filter_run.h>
#include <elastica/geometry.h>
#include <elastica/hole_filling.h>
#include <elastica/sign_convention.h>
#include <elastica/topology.h>

#include <algorithm>
#include <cstdio>

namespace elastica::filters {
namespace {

std::string number(double x, const char* fmt = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

// The enum value of `name`, checked against its spec (a script may carry any integer).
int enumValue(const ParamValues& v, const FilterSpec& spec, const std::string& name) {
  const int i = v.getEnum(name);
  const int n = static_cast<int>(spec.param(name)->enumValues.size());
  if (i < 0 || i >= n)
    throw InvalidInputError("parameter '" + name + "': enum value " + std::to_string(i) + " is not in 0.." +
                            std::to_string(n - 1));
  return i;
}

// Builds the topology and rejects what no flow can handle; the message says how to repair it in
// MeshLab. (Non-manifold edges are rejected by Topology itself.)
Topology checkedTopology(const TriMesh& mesh, bool rejectNonManifoldVertices) {
  if (mesh.faces.empty()) throw InvalidInputError("the mesh has no faces");
  Topology topo(mesh.vertexCount(), mesh.faces);
  if (topo.inconsistentEdgeCount() > 0)
    throw InvalidInputError("faces are not consistently oriented (" + std::to_string(topo.inconsistentEdgeCount()) +
                            " edges traversed the same way by both faces); re-orient them first: "
                            "Filters > Normals > Re-Orient all faces coherently");
  const int nonManifold = rejectNonManifoldVertices ? topo.nonManifoldVertexCount() : 0;  // counted per call
  if (nonManifold > 0)
    throw InvalidInputError(std::to_string(nonManifold) +
                            " non-manifold vertices (several fans of faces meet there); split them first: "
                            "Filters > Cleaning and Repairing > Repair non Manifold Vertices by splitting");
  return topo;
}

const char* stopText(StopReason s) {
  switch (s) {
    case StopReason::Converged: return "converged at the energy plateau";
    case StopReason::Stalled: return "stalled: no step lowers the energy any more";
    case StopReason::MaxSteps: return "stopped at maxSteps";
    case StopReason::MaxSeconds: return "stopped at the time limit";
    case StopReason::Cancelled: return "cancelled";
    case StopReason::Diverged: return "diverged";
  }
  return "?";
}

// flow, scheme and maxSteps: the parameters every flow filter has.
void readFlowParameters(const ParamValues& v, const FilterSpec& spec, FlowOptions& o) {
  o.flow = static_cast<FlowType>(enumValue(v, spec, "flow"));
  o.scheme = static_cast<Scheme>(enumValue(v, spec, "scheme"));
  o.maxSteps = v.getInt("maxSteps");
  if (o.maxSteps < 0) throw InvalidInputError("parameter 'maxSteps' must be >= 0");
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
  o.boundary = static_cast<BoundaryMode>(enumValue(v, spec, "boundary"));
  o.subdivisionLevels = v.getInt("subdivisionLevels");
  o.energyTolerance = v.getFloat("energyTolerance");
  o.tangentialDrift = v.getBool("tangentialDrift");
  if (o.subdivisionLevels < 0 || o.subdivisionLevels > 8)
    throw InvalidInputError("parameter 'subdivisionLevels' must be in 0..8");
  if (!(o.energyTolerance >= 0)) throw InvalidInputError("parameter 'energyTolerance' must be >= 0");
  return o;
}

FairingResult runFairing(TriMesh mesh, std::vector<std::uint8_t> selection, const ParamValues& v,
                         const Progress& progress) {
  FlowOptions opt = fairingOptions(v);
  const bool selected = v.getBool("Selected");
  checkedTopology(mesh, /*rejectNonManifoldVertices=*/true);
  if (selected && std::count(selection.begin(), selection.end(), 1) == 0)
    throw InvalidInputError("'Affect only selected faces' is on, but no face is selected");
  opt.progress = flowProgress(progress, opt.maxSteps);

  FairingResult r;
  const std::vector<Face> inputFaces = mesh.faces;
  const int inVertices = mesh.vertexCount();
  const FlowReport report = selected ? fair(mesh, FaceSet::fromFlags(selection), opt) : fair(mesh, opt);
  if (report.stop == StopReason::Cancelled) throw Error("cancelled; the mesh is unchanged");

  r.connectivityChanged = mesh.faces != inputFaces;
  r.colorByMeanCurvature = v.getBool("colorByMeanCurvature");
  if (r.colorByMeanCurvature) r.curvature = measureCurvature(mesh, {opt.area, opt.curvature});
  r.log.push_back(std::to_string(inVertices) + " -> " + std::to_string(mesh.vertexCount()) + " vertices, " +
                  std::to_string(report.steps) + " steps in " + number(report.seconds, "%.2f") + " s (" +
                  stopText(report.stop) + ")");
  r.log.push_back("total curvature energy " + number(report.energyInitial, "%.9g") + " -> " +
                  number(report.energyFinal, "%.9g"));
  r.mesh = std::move(mesh);
  if (selected) r.selection = FaceSet(report.regionFaces).flags(r.mesh.faces.size());
  return r;
}

HoleFillOptions fillHolesOptions(const ParamValues& v) {
  const FilterSpec spec = filterSpec(FilterId::FillHoles, {});
  HoleFillOptions o;
  o.maxHoleEdges = v.getInt("MaxHoleSize");
  if (o.maxHoleEdges < 3) throw InvalidInputError("parameter 'MaxHoleSize' must be >= 3 (a hole has 3 edges or more)");
  readFlowParameters(v, spec, o.flow);
  return o;
}

FillHolesResult runFillHoles(TriMesh mesh, const ParamValues& v, const Progress& progress) {
  HoleFillOptions opt = fillHolesOptions(v);
  checkedTopology(mesh, /*rejectNonManifoldVertices=*/true);
  opt.flow.progress = flowProgress(progress, opt.flow.maxSteps);

  FillHolesResult r;
  r.originalVertices = mesh.vertexCount();
  r.originalFaces = mesh.faceCount();
  const HoleFillReport report = fillHoles(mesh, opt);
  r.newFaces.assign(mesh.faces.size(), 0);
  for (std::size_t f = 0; f < r.newFaces.size(); ++f) r.newFaces[f] = report.isNewFace(static_cast<int>(f));
  for (const HoleReport& h : report.holes) {
    std::string line = "hole of " + std::to_string(h.borderEdges) + " border edges: ";
    if (h.filled)
      line += "filled with " + std::to_string(h.newVertices) + " vertices and " + std::to_string(h.newFaces) +
              " faces; patch energy " + number(h.energyBefore) + " -> " + number(h.energyAfter) + " in " +
              std::to_string(h.steps) + " steps (" + stopText(h.stop) + ")";
    else
      line += "left open";
    if (!h.reason.empty()) line += "; " + h.reason;
    r.log.push_back(line);
  }
  if (!report.welds.empty())
    r.log.push_back("merged " + std::to_string(report.welds.size()) +
                    " pairs of vertex copies at one point where a patch joined their fans");
  r.welds = report.welds;
  r.log.push_back("filled " + std::to_string(report.filledCount()) + " of " + std::to_string(report.holes.size()) +
                  " holes in " + number(report.seconds, "%.2f") + " s");
  r.mesh = std::move(mesh);
  return r;
}

CurvatureResult runCurvature(const TriMesh& mesh, const ParamValues& v) {
  const FilterSpec spec = filterSpec(FilterId::Curvature, {});
  const VertexArea area = static_cast<VertexArea>(enumValue(v, spec, "area"));
  const bool lambdaFix = v.getBool("lambdaFix");
  const Topology topo = checkedTopology(mesh, /*rejectNonManifoldVertices=*/false);

  CurvatureResult r;
  if (const int nonManifold = topo.nonManifoldVertexCount(); nonManifold > 0)  // counted per call
    r.log.push_back("warning: " + std::to_string(nonManifold) +
                    " non-manifold vertices; curvature there is not meaningful");
  const Geometry geo = computeGeometry(topo, mesh.positions, area);
  CurvatureOptions opt;
  opt.h2k = lambdaFix ? H2KTreatment::PaperLambda : H2KTreatment::Clamp;
  Curvature c = computeCurvature(topo, geo, mesh.positions, opt);
  auto [lo, hi] = std::minmax_element(c.H.begin(), c.H.end());
  // + 0.0 turns a negative zero into 0 for printing; the reported sign flips min and max.
  r.log.push_back("mean curvature H (+1/r on a sphere): " + number(reportedMeanCurvature(*hi) + 0.0) + " .. " +
                  number(reportedMeanCurvature(*lo) + 0.0));
  if (lambdaFix)
    r.log.push_back("paper's lambda fix: lambda = " + number(c.lambda) + " on " + std::to_string(c.lambdaVertices) +
                    " vertices");
  r.log.push_back("total curvature energy E = " + number(totalCurvatureEnergy(topo, geo, c), "%.9g"));
  // Values leave the core here: the reported sign (+1/r on an outward sphere).
  const std::vector<double>& H = lambdaFix ? c.Hflow : c.H;
  r.H.resize(H.size());
  std::transform(H.begin(), H.end(), r.H.begin(), reportedMeanCurvature);
  r.K = std::move(c.K);
  return r;
}

}  // namespace elastica::filters
