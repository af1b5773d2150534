// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/geometry.h>
#include <elastica/hole_filling.h>
#include <elastica/mesh_curvature.h>
#include <elastica/topology.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>

namespace elastica::app {
namespace {

std::string number(double x, const char* fmt = "%.6g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}

Topology checkedTopology(const TriMesh& mesh, bool rejectNonManifoldVertices) {
  return checkedTopology(mesh, rejectNonManifoldVertices, RepairHints::MeshLab);
}

}  // namespace

long long stepLimit(long long steps) { return steps == 0 ? std::numeric_limits<long long>::max() : steps; }

std::function<bool(const FlowProgress&)> flowProgress(const Progress& progress, const FlowOptions& o,
                                                      const Clock& clock) {
  if (!progress) return {};
  const Clock now = clock ? clock : [] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  };
  const double start = now();
  auto shown = std::make_shared<double>(0.0);  // the fraction shown last: progress never goes back
  const double stages = double(std::max(o.subdivisionLevels, 0) + 1);
  const double maxSeconds = o.maxSeconds;
  const double maxSteps = double(o.maxSteps);
  return [progress, now, start, shown, stages, maxSeconds, maxSteps](const FlowProgress& p) {
    const double seconds = now() - start;
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
  auto describe = [&spec](const char* name) { return spec.param(name)->describe(Caller::MeshLab); };
  if (stop == StopReason::MaxSeconds)
    return "stopped at the time limit of " + number(o.maxSeconds) +
           " s before the flow converged; the mesh is the state reached then. To let it run longer raise " +
           describe("maxSeconds") + " (0: no limit)" +
           (o.scheme == Scheme::Explicit ? ", or choose the Semi-implicit 'Time integration', which needs far "
                                           "fewer steps"
                                         : "");
  if (stop == StopReason::MaxSteps)
    return "stopped after " + std::to_string(o.maxSteps) +
           " steps before the flow converged; the mesh is the state reached then. To let it run longer raise " +
           describe("maxSteps") +
           (o.scheme == Scheme::Explicit ? ", or choose the Semi-implicit 'Time integration', which needs far "
                                           "fewer steps"
                                         : "");
  return {};
}

// The amount's roughness before and after (the region's faces, renumbered in the result), and
// for a result still rough the amount on the input to type instead: flow times add, and the time
// grows as the amount's 4th power, so the amount that adds the result's own is their 4-norm.
void measureRoughness(FairingResult::Amount& a, const TriMesh& input, const FaceSet* faces, const TriMesh& result,
                      const FlowReport& report) {
  const std::optional<FaceSet> after = faces ? std::optional<FaceSet>(FaceSet(report.regionFaces)) : std::nullopt;
  const FaceSet* resultFaces = after && !after->faces.empty() ? &*after : nullptr;
  a.roughnessBefore = surfaceRoughness(input, faces);
  a.roughnessAfter = surfaceRoughness(result, faces ? resultFaces : nullptr);
  if (a.roughnessAfter <= kRoughResult || (faces && !resultFaces)) return;
  const double more = autoFeatureSize(result, resultFaces);
  a.suggested = roundedAmount(std::pow(std::pow(a.featureSize, 4) + std::pow(more, 4), 0.25));
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

namespace {

// The vertices of a piece when a region's run checks and measures the whole mesh: small pieces
// keep their arrays in the cache (on a 416k-vertex scan 4,096 vertices took 0.52–0.60 s, 32,768
// 0.82–0.96 s, 131,072 1.31–1.42 s), but each piece scans every face, so at most kCheckPieces.
constexpr int kCheckPieceVertices = 1 << 12, kCheckPieces = 64;

// checkedTopology's checks (rejecting non-manifold vertices) and the whole mesh's energy. A
// region's run does both a piece at a time (measureCurvatureInPieces), building no whole-mesh
// Topology or Geometry, which were most of a small region's run on a large scan, much of it page
// faults of their fresh arrays (docs/decisions.md, "Curvature in pieces"). A piece that throws is checked again whole, for the mesh's own numbers.
double checkedEnergy(const TriMesh& mesh, const CurvatureMeasureOptions& measure, RepairHints hints, bool inPieces) {
  if (!inPieces) return measureCurvature(checkedTopology(mesh, /*rejectNonManifoldVertices=*/true, hints), mesh, measure).energy;
  if (mesh.faces.empty()) throw InvalidInputError("the mesh has no faces");
  MeshDefects defects;
  double energy = 0;
  try {
    const int pieceVertices = std::max(kCheckPieceVertices, mesh.vertexCount() / kCheckPieces + 1);
    energy = measureCurvatureInPieces(mesh, measure, pieceVertices, &defects).energy;
  } catch (const InvalidInputError&) {
    checkedTopology(mesh, /*rejectNonManifoldVertices=*/true, hints);
    throw;
  }
  rejectDefects(defects.inconsistentEdges, defects.nonManifoldVertices, hints);
  return energy;
}

}  // namespace

void checkFillInput(const TriMesh& mesh, RepairHints hints) {
  if (mesh.faces.empty()) throw InvalidInputError("the mesh has no faces");
  const FillInputDefects d = countFillInputDefects(mesh);
  rejectDefects(d.inconsistentEdges, d.nonManifoldVertices, hints);
}

FilterOutputs filterOutputs(FilterId id, const JobOptions& job) {
  switch (id) {
    case FilterId::Fairing: return {job.colorByMeanCurvature, job.selected};
    case FilterId::FillHoles: return {false, job.selectNewFaces};
    case FilterId::Curvature: return {true, false};
  }
  return {};
}

namespace {

// The flow on the whole mesh or the region. The default amount that raises the energy of what it
// fairs has collapsed a feature smaller than it into a needle (the principal part shrinks what it
// smooths): half of it, and so on. A region run says so itself (its guard gives the input back,
// StopReason::Unchanged). An amount the user chose runs as chosen; the log says when the energy
// rose. Returns the whole result's curvature when the halving rule measured it.
std::optional<MeshCurvature> fairHalvingTheAmount(TriMesh& mesh, const std::optional<FaceSet>& region,
                                                  FlowOptions& opt, const CurvatureMeasureOptions& measure,
                                                  const TriMesh& input, FairingResult& r) {
  const bool selected = region.has_value();
  const bool halve = r.amount.automatic && opt.featureSize > 0;
  std::optional<MeshCurvature> measured;
  for (;;) {
    r.report = selected ? fair(mesh, *region, opt) : fair(mesh, opt);
    if (r.report.stop == StopReason::Cancelled) throw Error("cancelled; the mesh is unchanged");
    if (!halve) break;
    if (!selected) measured = measureCurvature(mesh, measure);
    const bool rose = selected ? r.report.stop == StopReason::Unchanged : !(measured->energy < r.meshEnergyBefore);
    if (!rose) break;
    measured.reset();
    if (r.amount.halvings == kAmountHalvings) {
      mesh = input;
      r.report.stop = StopReason::Unchanged;
      r.report.refusedBecause = "every fairing amount down to " + number(opt.featureSize, "%.6g") +
                                " raised the energy";
      r.report.keptStage = -1;
      break;
    }
    ++r.amount.halvings;
    opt.featureSize /= 2;
    mesh = input;
  }
  return measured;
}

// How far the vertices moved, RMS and largest, when the run kept the connectivity.
void measureMotion(FairingResult& r, const TriMesh& input, const TriMesh& mesh) {
  r.connectivityChanged = mesh.faces != input.faces;
  const int inVertices = input.vertexCount();
  if (r.connectivityChanged || mesh.vertexCount() != inVertices) return;
  double sum = 0, largest = 0;
  for (int v = 0; v < inVertices; ++v) {
    const double d = (mesh.positions[v] - input.positions[v]).norm();
    sum += d * d;
    largest = std::max(largest, d);
  }
  r.movedRms = std::sqrt(sum / std::max(inVertices, 1));
  r.movedMax = largest;
}

// The whole mesh's energy after. A region's run changed the mesh near the region only: its energy
// after is the input's plus the change there (the same value up to the order of the sums), not a
// second whole-mesh measure (0.23 s of a 1,000-face region's run on a 280k-vertex scan).
void measureEnergyAfter(FairingResult& r, const TriMesh& input, const TriMesh& mesh,
                        const CurvatureMeasureOptions& measure, std::optional<MeshCurvature> measured, bool selected) {
  if (!measured && selected && !r.outputCurvature) {
    r.meshEnergyAfter = r.meshEnergyBefore + curvatureEnergyChange(input, mesh, measure);
    return;
  }
  if (!measured) measured = measureCurvature(mesh, measure);
  r.meshEnergyAfter = measured->energy;
  if (r.outputCurvature) r.curvature = std::move(*measured);
}

// The log's lines on the flow: counts and stop, a state not kept, the region's energy and
// resolution, the whole mesh's energy and the flow's own when its start differs.
void logFlow(FairingResult& r, int inVertices, int outVertices, bool selected) {
  const FlowReport& report = r.report;
  r.log.push_back({Severity::Info, std::to_string(inVertices) + " -> " + std::to_string(outVertices) +
                                       " vertices, " + std::to_string(report.steps) + " steps in " +
                                       number(report.seconds, "%.2f") + " s (" + labelOf(report.stop) + ")"});
  if (!report.refusedBecause.empty())
    r.log.push_back({Severity::Warning, "the flow's last state was not kept (" + report.refusedBecause + "): " +
                                            (report.keptStage < 0 ? std::string("the mesh is unchanged")
                                                                  : "the mesh is the state at the end of stage " +
                                                                        std::to_string(report.keptStage + 1) + " of " +
                                                                        std::to_string(report.stages.size()))});
  if (selected)
    r.log.push_back({Severity::Info, "region energy " + number(report.regionEnergyBefore, "%.9g") + " -> " +
                                         number(report.regionEnergyAfter, "%.9g") +
                                         " (the selected faces' vertices, fixed rings included)"});
  if (selected && !std::isnan(report.regionResolutionGap)) {
    const bool resolved = report.regionResolutionGap <= kRegionResolvedGap;
    r.resolutionLine = std::string("region ") + (resolved ? "resolved" : "not resolved") +
                       ": its energy Loop-subdivided once " + number(100 * report.regionResolutionGap, "%+.3g") + " %" +
                       (report.regionRuns > 1 ? std::string("; the vector scheme's first attempts or result were not resolved, "
                                                                "the semi-implicit scheme ran too, the ") +
                                                    nameOf(report.scheme) + " scheme's result came back"
                                              : "");
    r.log.push_back({resolved ? Severity::Info : Severity::Warning, r.resolutionLine});
  }
  r.log.push_back({Severity::Info, "total curvature energy " + number(r.meshEnergyBefore, "%.9g") + " -> " +
                                       number(r.meshEnergyAfter, "%.9g") + " (the whole mesh)"});
  // The flow's own start differs when it refined or remeshed the mesh first, or faired a region.
  if (!selected && std::abs(report.energyInitial - r.meshEnergyBefore) > 1e-9 * std::abs(r.meshEnergyBefore)) {
    r.flowEnergyLine = std::string("the flow's energy on its working mesh") +
                       (report.preSubdivisions + report.remeshings > 0 ? " after refinement or remeshing" : "") +
                       ": " + number(report.energyInitial, "%.9g") + " -> " + number(report.energyFinal, "%.9g");
    r.log.push_back({Severity::Info, r.flowEnergyLine});
  }
}

// The log's lines on the fairing amount (halvings, a rise, unused levels) and on a result still rough.
void logAmount(FairingResult& r, const FlowOptions& opt, bool selected) {
  const int h = r.amount.halvings;
  r.amountLine = "fairing amount: feature size " + exactDecimal(r.amount.featureSize) + " (" +
                 number(100 * r.amount.perDiagonal, "%.3g") + " % of the bounding-box diagonal, " +
                 number(r.amount.edges, "%.3g") + " mean edge lengths" + (r.amount.automatic ? ", auto" : "") + ")" +
                 (r.amount.operators == AmountOperators::Graph
                      ? ", uniform operators, twiced (roughness " + number(r.amount.roughnessBefore, "%.2g") + ")"
                      : "");
  if (h > 0)
    r.amountLine += ", halved " + std::to_string(h) + (h == 1 ? " time" : " times") +
                    ": a larger one raised the energy (a feature smaller than it collapsed)";
  const bool rose = !selected && !(r.meshEnergyAfter < r.meshEnergyBefore);
  if (rose && !r.amount.automatic)
    r.amountLine += "; the energy rose: a feature smaller than it collapsed (a smaller feature size may keep it)";
  // The vector scheme's amount keeps the mesh's vertices (fairing.cpp): levels asked for go unused.
  const bool levelsUnused = opt.subdivisionLevels > 0 && r.report.scheme == Scheme::Vector;
  if (levelsUnused)
    r.amountLine += "; the subdivision levels were not used (an amount keeps the mesh's vertices; feature size 0 "
                    "fairs coarse to fine, to the limit shape)";
  r.log.push_back({h > 0 || rose || levelsUnused ? Severity::Warning : Severity::Info, r.amountLine});
  if (r.amount.suggested > 0) {
    r.roughLine = "the result is still rough (roughness " + number(r.amount.roughnessAfter, "%.3g") + ", from " +
                  number(r.amount.roughnessBefore, "%.3g") + "; clean scans measure below " +
                  number(kRoughResult, "%.3g") + "): a feature size of " + exactDecimal(r.amount.suggested) +
                  " would smooth it further";
    r.log.push_back({Severity::Warning, r.roughLine});
  }
}

// The log's line on how far the vertices moved, in percent of the bounding-box diagonal.
void logMotion(FairingResult& r) {
  if (r.movedRms < 0 || r.diagonal <= 0) return;
  r.movedLine = "the vertices moved by " + number(100 * r.movedRms / r.diagonal, "%.3g") +
                " % of the bounding-box diagonal (RMS over the vertices), at most " +
                number(100 * r.movedMax / r.diagonal, "%.3g") + " %";
  r.log.push_back({Severity::Info, r.movedLine});
}

}  // namespace

// The run: check the options and the mesh, fair (halving the default amount while it raises the
// energy), measure the result, then say what happened.
FairingResult runFairing(TriMesh mesh, std::optional<FaceSet> region, const FlowOptions& requested,
                         bool outputCurvature, RepairHints hints) {
  FlowOptions opt = requested;
  FairingResult r;
  const FaceSet* faces = region ? &*region : nullptr;
  // "auto" is no amount where an amount has no meaning: the bilaplacian's time has no length unit,
  // and subdivision levels ask for coarse to fine, to the limit shape.
  r.amount.automatic = opt.featureSize == kAutoFeatureSize;
  const bool amountMeaningful = opt.flow != FlowType::Bilaplacian && opt.subdivisionLevels == 0;
  const AutoAmount own = amountMeaningful ? autoAmount(mesh, faces) : AutoAmount{};
  if (r.amount.automatic) opt.featureSize = own.featureSize;
  // Any amount runs with the operators the default would (a rough scan's uniform ones): the
  // default's printed amount typed back gives its output.
  opt.amountOperators = own.operators;
  JobOptions job;
  job.flow = opt;
  checkOptions(FilterId::Fairing, job);
  const CurvatureMeasureOptions measure{opt.area, opt.curvature};
  r.meshEnergyBefore = checkedEnergy(mesh, measure, hints, /*inPieces=*/region.has_value());
  if (region && region->faces.empty()) throw InvalidInputError("the region to fair has no faces");
  const bool selected = region.has_value();
  const TriMesh input = mesh;
  r.diagonal = boundingBoxDiagonal(mesh.positions);
  const double meanEdge = meanFaceEdge(mesh, faces);

  std::optional<MeshCurvature> measured = fairHalvingTheAmount(mesh, region, opt, measure, input, r);
  r.amount.featureSize = opt.featureSize > 0 ? opt.featureSize : 0;
  r.amount.operators = opt.amountOperators;
  r.amount.edges = meanEdge > 0 ? r.amount.featureSize / meanEdge : 0;
  r.amount.perDiagonal = r.diagonal > 0 ? r.amount.featureSize / r.diagonal : 0;
  if (r.amount.featureSize > 0) measureRoughness(r.amount, input, faces, mesh, r.report);
  measureMotion(r, input, mesh);
  r.outputCurvature = outputCurvature;
  measureEnergyAfter(r, input, mesh, measure, std::move(measured), selected);

  logFlow(r, input.vertexCount(), mesh.vertexCount(), selected);
  if (r.amount.featureSize > 0) logAmount(r, opt, selected);
  logMotion(r);
  r.mesh = std::move(mesh);
  if (selected) r.region = FaceSet(r.report.regionFaces);
  return r;
}

FairingResult runFairing(TriMesh mesh, std::optional<FaceSet> selection, const ParamValues& v,
                         const Progress& progress) {
  JobOptions job = readJob(filterSpec(FilterId::Fairing, {}), v, Caller::MeshLab);
  // The dialog's default feature size is the mesh's own amount (MeshFacts::featureSize: over the
  // selected faces if any, in MeshLab's float): left as it was, it is "auto" (halved if it raised
  // the energy), as on the other faces.
  const double own = autoFeatureSize(mesh, selection && !selection->faces.empty() ? &*selection : nullptr);
  if (job.flow.featureSize > 0 && std::abs(job.flow.featureSize - own) <= 1e-6 * own)
    job.flow.featureSize = kAutoFeatureSize;
  if (!job.selected)
    selection.reset();
  else if (!selection || selection->faces.empty())
    throw InvalidInputError("'Affect only selected faces' is on, but no face is selected");
  const bool selected = job.selected;
  FlowOptions& opt = job.flow;
  opt.progress = flowProgress(progress, opt);
  // The dialog always carries a feature size (the mesh's amount by default), so the Bilaplacian,
  // whose time has no length unit, is not refused here as the CLI refuses it: it runs to its own stop.
  std::vector<LogLine> notes;
  if (opt.flow == FlowType::Bilaplacian && opt.featureSize != 0) {
    opt.featureSize = 0;
    notes.push_back({Severity::Info, "the Bilaplacian flow takes no feature size (its time has no length unit); "
                                     "it ran to its own stop"});
  }
  FairingResult r = runFairing(std::move(mesh), std::move(selection), opt, job.colorByMeanCurvature, RepairHints::MeshLab);
  r.log.insert(r.log.begin(), notes.begin(), notes.end());
  const std::string warning = limitWarning(r.report.stop, filterSpec(FilterId::Fairing, {}), opt);
  if (!warning.empty()) r.log.push_back({Severity::Warning, warning});
  const int levels = r.report.stages.empty() ? 0 : r.report.stages.back().level;
  if (selected && levels > 0)
    r.log.push_back({Severity::Info, "only the selected faces were subdivided (" + std::to_string(levels) +
                                         (levels == 1 ? " level" : " levels") +
                                         "; the faces along the selection were split to keep the mesh conforming); "
                                         "only they moved, and they are selected in the refined mesh"});
  return r;
}

FillHolesResult runFillHoles(TriMesh mesh, const HoleFillOptions& opt, bool outputCurvature) {
  JobOptions job;
  job.fill = opt;
  checkOptions(FilterId::FillHoles, job);
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
              " faces; patch energy " + number(h.energyBefore) + " -> " + number(h.energyAfter) +
              (h.steps == 0 && h.stop == StopReason::Unchanged
                   ? std::string(" (no flow)")  // HoleReport::reason says why, where it matters
                   : " in " + std::to_string(h.steps) + " steps (" + labelOf(h.stop) + ")");
    else
      line += "left open";
    if (!h.reason.empty()) line += "; " + h.reason;
    r.log.push_back({Severity::Info, line});
  }
  if (!report.welds.empty())
    r.log.push_back({Severity::Info, "merged " + std::to_string(report.welds.size()) +
                                         " pairs of vertex copies at one point where a patch joined their fans"});
  r.log.push_back({Severity::Info, "filled " + std::to_string(report.filledCount()) + " of " +
                                       std::to_string(report.holes.size()) + " holes in " +
                                       number(report.seconds, "%.2f") + " s"});
  r.mesh = std::move(mesh);
  return r;
}

FillHolesResult runFillHoles(TriMesh mesh, const ParamValues& v, const Progress& progress) {
  const FilterSpec spec = filterSpec(FilterId::FillHoles, {});
  HoleFillOptions opt = readJob(spec, v, Caller::MeshLab).fill;
  checkFillInput(mesh, RepairHints::MeshLab);
  opt.flow.progress = flowProgress(progress, opt.flow);
  FillHolesResult r = runFillHoles(std::move(mesh), opt);
  std::string warning;
  for (const HoleReport& h : r.report.holes)
    if (warning.empty() && h.filled) warning = limitWarning(h.stop, spec, opt.flow);
  if (!warning.empty()) r.log.push_back({Severity::Warning, warning});
  if (r.report.holes.empty())
    r.log = {{Severity::Info, "the mesh has no holes: nothing to fill; the mesh and its selection are unchanged"}};
  else if (r.report.filledCount() == 0)
    r.log.push_back({Severity::Info, "no hole was filled: the mesh and its selection are unchanged"});
  return r;
}

CurvatureResult runCurvature(const TriMesh& mesh, const CurvatureMeasureOptions& opt) {
  CurvatureResult r;
  // Above a million vertices, in pieces: at 2.6 M a whole-mesh Topology, Geometry and Curvature
  // took 1,421 MB (meshlabserver reads and writes the file in 483 MB), in pieces 580 MB at 1.27×
  // the time (farm-bench, paired, at 2ff5174; the pieces are faster since: docs/benchmarks.md,
  // I/O); below it the whole mesh's caches stay within 2× of MeshLab's
  // memory (655 k vertices: 361 MB against 198 MB) and the time is kept.
  constexpr int kPiecesAbove = 1 << 20;
  r.curvature = mesh.vertexCount() > kPiecesAbove ? measureCurvatureInPieces(mesh, opt) : measureCurvature(mesh, opt);
  r.lambdaFix = opt.curvature.h2k == H2KTreatment::PaperLambda;
  const MeshCurvature& c = r.curvature;
  auto [lo, hi] = std::minmax_element(c.H.begin(), c.H.end());
  // + 0.0 turns a negative zero into 0 for printing.
  if (!c.H.empty())
    r.log.push_back({Severity::Info,
                     "mean curvature H (+1/r on a sphere): " + number(*lo + 0.0) + " .. " + number(*hi + 0.0)});
  if (r.lambdaFix)
    r.log.push_back({Severity::Info, "paper's lambda fix: lambda = " + number(c.lambda) + " on " +
                                         std::to_string(c.lambdaVertices) + " vertices (H written is H/lambda there)"});
  const DegeneracyCounts& d = c.degenerate;
  if (d.total() > 0)
    r.log.push_back({Severity::Info, "degenerate, given zero weight: " + std::to_string(d.zeroAreaFaces) +
                                         " zero-area faces, " + std::to_string(d.zeroLengthEdges) +
                                         " zero-length edges, " + std::to_string(d.zeroAreaVertices) +
                                         " vertices without area, " + std::to_string(d.isolatedVertices) +
                                         " isolated vertices"});
  r.log.push_back({Severity::Info, "total curvature energy E = " + number(c.energy, "%.9g")});
  return r;
}

CurvatureResult runCurvature(const TriMesh& mesh, const ParamValues& v) {
  const CurvatureMeasureOptions opt = readJob(filterSpec(FilterId::Curvature, {}), v, Caller::MeshLab).curvature;
  const Topology topo = checkedTopology(mesh, /*rejectNonManifoldVertices=*/false);
  const int nonManifold = topo.nonManifoldVertexCount();  // counted per call
  CurvatureResult r = runCurvature(mesh, opt);
  if (nonManifold > 0)
    r.log.insert(r.log.begin(), {Severity::Warning, std::to_string(nonManifold) +
                                                        " non-manifold vertices; curvature there is not meaningful"});
  return r;
}

}  // namespace elastica::app
