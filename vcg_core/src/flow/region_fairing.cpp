// SPDX-License-Identifier: GPL-3.0-or-later
// fair(mesh, region): a selected region of a mesh, faired at the region's cost. The run works on
// a piece of the mesh (the region, the rings around it that its operators read, and the faces near
// it that it could run into), checked there by the region guard (flow/region_guard.h), and the
// piece's result is spliced back into the mesh. Nothing in a step, a stage or the checks touches
// the rest of the mesh: a region of 1,000 faces costs the same on a scan of 17,000 vertices as on
// one of 280,000.
#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/topology.h>
#include <elastica/vertex_faces.h>
#include "flow/constraints.h"
#include "flow/fair_masked.h"
#include "flow/region_guard.h"
#include "flow/region_resolution.h"
#include "mesh/box.h"
#include "mesh/self_intersection.h"
#include "mesh/submesh.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

namespace elastica {
namespace {

// The piece around the region: every face within kPieceRings face-rings of the region's vertices.
// The flow moves the region's interior vertices; the vertices of its border (ring 1 of the flow,
// where H is evaluated) and their outer neighbours (ring 2) stay fixed, and the operators at ring 1
// read the whole fans of ring 2. Three rings give every vertex up to ring 2 its whole fan, and one
// more row of faces beyond (curvature stiffness and normals at ring 2 read no farther).
constexpr int kPieceRings = 3;
// The faces of the rest of the mesh whose boxes meet the region's box grown by this fraction of its
// diagonal join the piece as obstacles (fixed faces, flagged off the region): the flow's embedding
// guard and the region guard's crossing test see them, so a region cannot pass through a part of
// the scan beside it (a finger against the next one, an ear against the head). A region whose
// result leaves that box is checked against the whole mesh's faces there (crossesOutside).
constexpr double kObstacleMargin = 0.25;

// The box of the flagged faces.
Box boxOfFlagged(const TriMesh& mesh, const std::vector<std::uint8_t>& flags) {
  Box b;
  for (int f = 0; f < mesh.faceCount(); ++f)
    if (flags[f])
      for (int v : mesh.faces[f]) b.add(mesh.positions[v]);
  return b;
}

// The piece a region's run works on, numbered so that the splice can read the run's result back:
// the vertices that never move or go (every vertex but the free ones) first, the free ones after,
// in the mesh's order; the faces off the region first, the region's after, in the mesh's order.
// Remeshing keeps the vertices that do not move at their index, fills the freed slots of those
// that go with those that remain and appends new ones; it keeps faces off the region at their
// index and refills dead slots from the end (mesh/patch_remeshing.h): so in the piece's result,
// vertex i < keptVertices is vertex i of the piece and face f < outsideFaces is face f of the piece.
struct Piece {
  TriMesh mesh;
  std::vector<std::uint8_t> selection;  // per face of the piece: in the region
  std::vector<std::uint8_t> sliding;    // per vertex of the piece: slides along the border (Slide mode)
  std::vector<int> vertex;              // piece vertex → mesh vertex
  std::vector<int> face;                // piece face → mesh face
  int keptVertices = 0, outsideFaces = 0;
  std::vector<int> freeSlots;  // the mesh vertices that move, ascending (= vertex[keptVertices…])
  Box obstacleBox;             // every face of the mesh that meets it is in the piece
};

// The piece around `selection`'s faces, or nothing if it would hold every face of the mesh.
std::optional<Piece> pieceAround(const TriMesh& mesh, const std::vector<std::uint8_t>& selection, BoundaryMode mode) {
  const int nv = mesh.vertexCount(), nf = mesh.faceCount();
  for (int f = 0; f < nf; ++f)
    for (int v : mesh.faces[f])
      if (v < 0 || v >= nv)
        throw InvalidInputError("fair: face " + std::to_string(f) + " has a vertex index out of range");
  std::vector<int> seeds;
  {
    std::unordered_map<int, char> seen;
    for (int f = 0; f < nf; ++f)
      if (selection[f])
        for (int v : mesh.faces[f])
          if (seen.emplace(v, 0).second) seeds.push_back(v);
  }
  Submesh sub;
  {
    const VertexFaces adjacency(nv, mesh.faces);
    sub = extractSubmesh(mesh, adjacency, seeds, kPieceRings);
  }
  if (static_cast<int>(sub.face.size()) == nf) return std::nullopt;

  // The obstacles: the rest's faces near the region.
  std::vector<std::uint8_t> regionFlags(sub.face.size());
  for (std::size_t f = 0; f < sub.face.size(); ++f) regionFlags[f] = selection[sub.face[f]];
  const Box regionBox = boxOfFlagged(sub.mesh, regionFlags);
  Piece p;
  p.obstacleBox = regionBox.grown(kObstacleMargin * (regionBox.hi - regionBox.lo).norm());
  {
    std::vector<std::uint8_t> inSub(nf, 0);
    for (int f : sub.face) inSub[f] = 1;
    std::unordered_map<int, int> local;
    for (std::size_t i = 0; i < sub.vertex.size(); ++i) local.emplace(sub.vertex[i], static_cast<int>(i));
    for (int f = 0; f < nf; ++f) {
      if (inSub[f] || !boxOf(mesh, mesh.faces[f]).meets(p.obstacleBox)) continue;
      Face t;
      for (int k = 0; k < 3; ++k) {
        const int v = mesh.faces[f][k];
        const auto [at, added] = local.emplace(v, static_cast<int>(sub.vertex.size()));
        if (added) {
          sub.vertex.push_back(v);
          sub.mesh.positions.push_back(mesh.positions[v]);
        }
        t[k] = at->second;
      }
      sub.mesh.faces.push_back(t);
      sub.face.push_back(f);
    }
  }

  // The order the splice reads back (see Piece).
  std::vector<std::uint8_t> subSelection(sub.face.size());
  for (std::size_t f = 0; f < sub.face.size(); ++f) subSelection[f] = selection[sub.face[f]];
  const Topology topo(sub.mesh.vertexCount(), sub.mesh.faces);
  const VertexRoles roles = assignRoles(topo, &subSelection, mode);
  std::vector<int> vertexOrder(sub.vertex.size());
  std::iota(vertexOrder.begin(), vertexOrder.end(), 0);
  std::stable_sort(vertexOrder.begin(), vertexOrder.end(), [&](int a, int b) {
    if (roles.free[a] != roles.free[b]) return roles.free[a] < roles.free[b];
    return sub.vertex[a] < sub.vertex[b];
  });
  std::vector<int> faceOrder(sub.face.size());
  std::iota(faceOrder.begin(), faceOrder.end(), 0);
  std::stable_sort(faceOrder.begin(), faceOrder.end(), [&](int a, int b) {
    if (subSelection[a] != subSelection[b]) return subSelection[a] < subSelection[b];
    return sub.face[a] < sub.face[b];
  });
  std::vector<int> newIndex(sub.vertex.size());
  for (std::size_t i = 0; i < vertexOrder.size(); ++i) {
    const int old = vertexOrder[i];
    newIndex[old] = static_cast<int>(i);
    p.vertex.push_back(sub.vertex[old]);
    p.mesh.positions.push_back(sub.mesh.positions[old]);
    p.sliding.push_back(roles.sliding[old]);
    if (roles.free[old]) p.freeSlots.push_back(sub.vertex[old]);
    else ++p.keptVertices;
  }
  for (int old : faceOrder) {
    const Face& t = sub.mesh.faces[old];
    p.mesh.faces.push_back({newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]});
    p.face.push_back(sub.face[old]);
    p.selection.push_back(subSelection[old]);
    p.outsideFaces += !subSelection[old];
  }
  return p;
}

std::uint64_t bitsOf(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Whether the run kept what the splice relies on (Piece): the vertices before keptVertices where
// they were (but the sliding ones), and without subdivision the faces before outsideFaces as they
// were. "" if it did, else what it did not keep.
std::string pieceKept(const Piece& in, const TriMesh& out, bool subdivided) {
  if (out.vertexCount() < in.keptVertices || out.faceCount() < in.outsideFaces)
    return "the run lost a vertex or a face off the region";
  for (int i = 0; i < in.keptVertices; ++i)
    if (!in.sliding[i])
      for (int d = 0; d < 3; ++d)
        if (bitsOf(out.positions[i][d]) != bitsOf(in.mesh.positions[i][d])) return "a vertex off the region moved";
  if (!subdivided)
    for (int f = 0; f < in.outsideFaces; ++f)
      if (out.faces[f] != in.mesh.faces[f]) return "a face off the region changed";
  return {};
}

// The faces of `mesh` off the piece that meet `box`, as faces of `piece` (new vertices appended).
// The faces of the piece keep their indices; returns how many it had.
int addFacesMeeting(const TriMesh& mesh, const Piece& in, TriMesh& piece, const Box& box) {
  const int before = piece.faceCount();
  std::vector<std::uint8_t> inPiece(mesh.faces.size(), 0);
  for (int f : in.face) inPiece[f] = 1;
  std::unordered_map<int, int> local;
  for (int i = 0; i < in.keptVertices; ++i) local.emplace(in.vertex[i], i);  // the free ones have no outside face
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (inPiece[f] || !boxOf(mesh, mesh.faces[f]).meets(box)) continue;
    Face t;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.faces[f][k];
      const auto [at, added] = local.emplace(v, piece.vertexCount());
      if (added) piece.positions.push_back(mesh.positions[v]);
      t[k] = at->second;
    }
    piece.faces.push_back(t);
  }
  return before;
}

// The crossings of the region's faces and their neighbours with the rest of the mesh, counted on
// the piece with every face of `mesh` that meets `box` added: for a result that left the obstacle
// box, the guard's crossing test did not see everything it could run into.
int crossingsNear(const TriMesh& mesh, const Piece& in, TriMesh piece, const std::vector<std::uint8_t>& selection,
                  const Box& box) {
  std::vector<std::uint8_t> regionVertex(piece.positions.size(), 0);
  for (int f = 0; f < piece.faceCount(); ++f)
    if (selection[f])
      for (int v : piece.faces[f]) regionVertex[v] = 1;
  std::vector<std::uint8_t> near(piece.faces.size(), 0);
  for (int f = 0; f < piece.faceCount(); ++f)
    for (int v : piece.faces[f]) near[f] |= regionVertex[v];
  addFacesMeeting(mesh, in, piece, box);
  near.resize(piece.faces.size(), 0);
  return static_cast<int>(selfIntersectingFaces(piece, &near).size());
}

// Writes the piece's result `out` (its region's flags `outSelection`) into `mesh` (see fairing.h
// for the order) and returns the region's faces in the mesh, ascending.
std::vector<int> splice(TriMesh& mesh, const Piece& in, const TriMesh& out, const std::vector<std::uint8_t>& outSelection) {
  const int nv = mesh.vertexCount();
  const int movedSlots = static_cast<int>(in.freeSlots.size());
  const int moving = out.vertexCount() - in.keptVertices;  // free and new vertices of the result
  auto global = [&](int i) {
    if (i < in.keptVertices) return in.vertex[i];
    const int j = i - in.keptVertices;
    return j < movedSlots ? in.freeSlots[j] : nv + (j - movedSlots);
  };
  if (moving > movedSlots) mesh.positions.resize(nv + (moving - movedSlots));
  for (int i = 0; i < out.vertexCount(); ++i)
    if (i >= in.keptVertices || in.sliding[i]) mesh.positions[global(i)] = out.positions[i];
  const int slots = static_cast<int>(in.face.size());
  std::vector<int> region;
  for (int f = 0; f < out.faceCount(); ++f) {
    const Face& t = out.faces[f];
    const Face g{global(t[0]), global(t[1]), global(t[2])};
    int at = f < slots ? in.face[f] : mesh.faceCount();
    if (f < slots) mesh.faces[at] = g;
    else mesh.faces.push_back(g);
    if (outSelection[f]) region.push_back(at);
  }
  // Slots the region gave up (it came back with fewer faces or fewer vertices than it had): the
  // elements after them move down, in their order.
  if (out.faceCount() < slots) {
    std::vector<std::uint8_t> dead(mesh.faces.size(), 0);
    for (int f = out.faceCount(); f < slots; ++f) dead[in.face[f]] = 1;
    std::vector<int> index(mesh.faces.size(), -1);
    int next = 0;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
      if (!dead[f]) index[f] = next, mesh.faces[next++] = mesh.faces[f];
    mesh.faces.resize(next);
    for (int& f : region) f = index[f];
  }
  if (moving < movedSlots) {
    std::vector<int> index(mesh.positions.size(), 0);
    for (int j = moving; j < movedSlots; ++j) index[in.freeSlots[j]] = -1;
    int next = 0;
    for (std::size_t v = 0; v < index.size(); ++v)
      if (index[v] == 0) index[v] = next, mesh.positions[next++] = mesh.positions[v];
    mesh.positions.resize(next);
    for (Face& t : mesh.faces)
      for (int& v : t) v = index[v];
  }
  std::sort(region.begin(), region.end());
  return region;
}

// The region's run on `mesh` as a whole (the piece, or a mesh that the piece would cover), its
// result checked by the region guard: what fair(mesh, region) promises, on `mesh`. `selection`
// comes back as the result's region flags. On a FlowDivergedError, `mesh` and `selection` are the
// last state that passed.
FlowReport fairGuarded(TriMesh& mesh, std::vector<std::uint8_t>& selection, const FlowOptions& opt) {
  // Whatever the run reached, the mesh that comes back passes the guard's checks. If the run's last
  // state fails them, the last stage end that passed comes back, else the input (region_guard.h).
  const RegionGuard guard(mesh, selection, opt);
  struct Kept {
    TriMesh mesh;
    std::vector<std::uint8_t> selection;
    double energy = 0;
    int stage = 0;
  };
  Kept kept{mesh, selection, guard.energyBefore(), -1};
  int stagesEnded = 0;
  const StageEnded stageEnded = [&](const TriMesh& m, const std::vector<std::uint8_t>& s) {
    double energy = 0;
    if (guard.check(m, s, energy).empty()) kept = {m, s, energy, stagesEnded};
    ++stagesEnded;
  };
  FlowReport report;
  try {
    report = fairMasked(mesh, &selection, opt, {}, stageEnded);
  } catch (FlowDivergedError&) {
    mesh = std::move(kept.mesh);  // a diverged run's last state is not kept either (the contract)
    selection = std::move(kept.selection);
    throw;
  }
  report.regionEnergyBefore = guard.energyBefore();
  report.refusedBecause = guard.check(mesh, selection, report.regionEnergyAfter);
  if (!report.refusedBecause.empty()) {
    mesh = std::move(kept.mesh);
    selection = std::move(kept.selection);
    report.regionEnergyAfter = kept.energy;
    report.keptStage = kept.stage;
    if (kept.stage < 0) report.stop = StopReason::Unchanged;
  }
  return report;
}

// Whether a region's run is one that fairResolved checks: the default scheme run to its limit
// shape (the elastica flow, remeshing on, no fairing amount). A scheme the user chose is run as
// asked, and a fairing amount keeps the user's vertices and moves them little.
bool checksResolution(const FlowOptions& opt) {
  return opt.scheme == Scheme::Automatic && opt.flow == FlowType::Elastica && opt.remesh && !(opt.featureSize > 0);
}

// fairResolved's second run may take this many times the first run's attempts (a count, so that
// the output does not depend on the machine). A semi-implicit attempt costs about a third of a
// vector one on a region, and that scheme needs somewhat more of them (docs/decisions.md, "Regions": resolved
// regions).
constexpr long long kSecondRunAttempts = 2;
// fairResolved's probe: the vector scheme's first kLidProbeAttempts attempts. A region it will
// leave as a lid already reads as one there, and one it resolves does not, on the recipe regions
// measured (docs/decisions.md, "Regions": resolved regions); the
// golden outputs' cow region does, and its vector result is resolved: it pays for all three runs
// (429 → 563 attempts, the same mesh). Such a region runs the semi-implicit scheme first, with at
// most kSemiFirstAttempts attempts; the whole vector run follows only if that result is not
// converged and resolved.
constexpr long long kLidProbeAttempts = 20, kSemiFirstAttempts = 25 * kLidProbeAttempts;

// One run of fairResolved from the input: its mesh, selection, report and resolution.
struct ResolvedRun {
  TriMesh mesh;
  std::vector<std::uint8_t> selection;
  FlowReport report;
  RegionResolution resolution;
  bool ran = false;
};

// A stop fair() calls final when the region is resolved: converged, or pressed against itself.
bool saysFinal(StopReason stop) { return stop == StopReason::Converged || stop == StopReason::SelfContact; }

// A run fairResolved may call final (a resolved region and a final stop): it beats one that is not.
bool isFinal(const ResolvedRun& r) { return saysFinal(r.report.stop) && r.resolution.resolved(); }

// A semi-implicit run before the vector run that makes the whole vector run unneeded
// (kSemiFirstAttempts): converged and resolved; a stop pressed against itself is not enough.
bool sparesVectorRun(const ResolvedRun& r) { return r.report.stop == StopReason::Converged && r.resolution.resolved(); }

// fairGuarded from `mesh` and `selection` (copied) with `opt`. A semi-implicit run that diverges
// counts as unchanged (the vector scheme's result stands); the vector scheme's divergence is the
// caller's FlowDivergedError, as a run of fairGuarded alone.
ResolvedRun runFrom(const TriMesh& mesh, const std::vector<std::uint8_t>& selection, const FlowOptions& opt) {
  ResolvedRun run{mesh, selection, {}, {}, true};
  try {
    run.report = fairGuarded(run.mesh, run.selection, opt);
  } catch (const FlowDivergedError&) {
    if (opt.scheme != Scheme::SemiImplicit) throw;
    run.mesh = mesh, run.selection = selection;
    run.report.stop = StopReason::Unchanged;
  }
  run.resolution = measureRegionResolution(run.mesh, run.selection, opt);
  return run;
}

// fairGuarded with Scheme::Automatic (the vector scheme), and if its result does not resolve the
// region (region_resolution.h: a faceted lid), the semi-implicit scheme from the same input too,
// whose steps move vertices only along their normals and whose tangential drift evens them out:
// a final one (converged, resolved) over one that is not, else the one whose region costs less
// once its mesh's errors are counted (resolvedEnergy) comes back.
// Neither is better everywhere: on lion-head's recipe regions the vector scheme's lids cost up to
// twice the semi-implicit result, and where it does not facet it ends lower (docs/decisions.md,
// "Regions"). The second run may take kSecondRunAttempts times the first run's
// attempts, within the user's limits. A region whose probe (kLidProbeAttempts) is already a lid
// runs the semi-implicit scheme first, and keeps its result if it converged resolved. Every
// attempt, the probe's too, counts against the user's limits and in the report. A result that is
// still not resolved does not say converged: it says stalled.
FlowReport fairResolved(TriMesh& mesh, std::vector<std::uint8_t>& selection, const FlowOptions& opt) {
  if (!checksResolution(opt)) return fairGuarded(mesh, selection, opt);
  long long steps = 0, rejected = 0;
  double seconds = 0;
  auto spend = [&](const FlowReport& r) { steps += r.steps, rejected += r.rejectedSteps, seconds += r.seconds; };
  // The options of a run from here: the user's limits less what the runs so far spent.
  auto remaining = [&](Scheme scheme, long long cap) {
    FlowOptions o = opt;
    o.scheme = scheme;
    o.maxSteps = std::min(opt.maxSteps - std::min(opt.maxSteps, steps), cap);
    if (opt.maxSeconds > 0) o.maxSeconds = opt.maxSeconds - seconds;
    return o;
  };
  auto canRun = [&](const FlowOptions& o) { return o.maxSteps > 0 && (!(opt.maxSeconds > 0) || o.maxSeconds > 0); };
  ResolvedRun probe, vector, semi;
  // Only where the user's step limit leaves the probe and the semi-implicit run room beside the
  // whole vector run: under a tighter one they would take the attempts it needs.
  if (opt.maxSteps > 4 * (kLidProbeAttempts + kSemiFirstAttempts)) {
    probe = runFrom(mesh, selection, remaining(Scheme::Automatic, kLidProbeAttempts));
    spend(probe.report);
    // A probe that stopped before its attempts ran out is the whole vector run (the same run).
    if (probe.report.stop != StopReason::MaxSteps) std::swap(vector, probe);
    else if (!probe.resolution.resolved() && canRun(remaining(Scheme::SemiImplicit, kSemiFirstAttempts))) {
      semi = runFrom(mesh, selection, remaining(Scheme::SemiImplicit, kSemiFirstAttempts));
      spend(semi.report);
    }
  }
  const FlowOptions whole = remaining(Scheme::Automatic, opt.maxSteps);
  if (!vector.ran && !(semi.ran && sparesVectorRun(semi)) && canRun(whole)) {
    vector = runFrom(mesh, selection, whole);
    spend(vector.report);
  }
  if (vector.ran && !semi.ran && !vector.resolution.resolved() && !stoppedAtALimit(vector.report.stop)) {
    const FlowOptions second = remaining(Scheme::SemiImplicit, std::max(kSecondRunAttempts * vector.report.steps, 1LL));
    if (canRun(second)) {
      semi = runFrom(mesh, selection, second);
      spend(semi.report);
    }
  }
  // The semi-implicit result comes back if it is the only one, or changed the region and is final
  // where the vector result is not, or neither or both are and it costs less (or the vector run
  // changed nothing). A final result beats a lid whose Loop surface costs less: that surface is
  // not the mesh that comes back, and the lid would say stalled (docs/decisions.md, "Regions:
  // which run comes back").
  const bool takeSemi = semi.ran && semi.report.stop != StopReason::Unchanged &&
                        (!vector.ran || vector.report.stop == StopReason::Unchanged ||
                         (isFinal(semi) != isFinal(vector) ? isFinal(semi)
                                                           : semi.resolution.resolvedEnergy() < vector.resolution.resolvedEnergy()));
  // Neither changed the region nor the vector scheme ran (the user's time limit): the probe's result.
  ResolvedRun& chosen = takeSemi ? semi : vector.ran ? vector : probe.ran ? probe : semi;
  const bool probeCameBack = &chosen == &probe;
  const int runs = int(probe.ran || vector.ran) + int(semi.ran);  // the schemes that ran
  mesh = std::move(chosen.mesh);
  selection = std::move(chosen.selection);
  FlowReport report = std::move(chosen.report);
  // The attempts a semi-implicit run ran out of were this function's, not the user's.
  if (takeSemi && report.stop == StopReason::MaxSteps && steps < opt.maxSteps) report.stop = StopReason::Stalled;
  if (probeCameBack && report.stop == StopReason::MaxSteps && steps < opt.maxSteps) report.stop = StopReason::MaxSeconds;
  report.steps = steps;
  report.rejectedSteps = rejected;
  report.seconds = seconds;
  report.regionRuns = runs;
  report.regionResolutionGap = chosen.resolution.gap();
  if (!chosen.resolution.resolved() && saysFinal(report.stop)) report.stop = StopReason::Stalled;
  return report;
}

}  // namespace

FlowReport fair(TriMesh& mesh, const FaceSet& region, const FlowOptions& opt) {
  std::vector<std::uint8_t> selection;
  try {
    selection = region.flags(mesh.faces.size());
  } catch (const InvalidInputError& e) {
    throw InvalidInputError(std::string("fair: the region's ") + e.what());
  }
  validateFlowOptions(opt);
  std::optional<Piece> piece = pieceAround(mesh, selection, opt.boundary);
  if (!piece) {  // the region and its rings are the whole mesh: the run works on it in place
    FlowReport report = fairResolved(mesh, selection, opt);
    report.regionFaces = FaceSet::fromFlags(selection).faces;
    return report;
  }
  TriMesh result = piece->mesh;
  std::vector<std::uint8_t> resultSelection = piece->selection;
  FlowReport report;
  try {
    report = fairResolved(result, resultSelection, opt);
  } catch (FlowDivergedError&) {
    if (pieceKept(*piece, result, opt.subdivisionLevels > 0).empty()) splice(mesh, *piece, result, resultSelection);
    throw;
  }
  // What the splice relies on, and crossings beyond the obstacles. Either failing is refused as the
  // guard refuses (the input comes back): neither happens by construction, but a promise about the
  // rest of a user's scan is checked, not assumed.
  std::string refused = pieceKept(*piece, result, opt.subdivisionLevels > 0);
  if (refused.empty() && report.stop != StopReason::Unchanged) {
    const Box reached = boxOfFlagged(result, resultSelection);
    if (!piece->obstacleBox.contains(reached) &&
        crossingsNear(mesh, *piece, result, resultSelection, reached) >
            crossingsNear(mesh, *piece, piece->mesh, piece->selection, reached))
      refused = "faces of the region cross the mesh beyond the faces near it";
  }
  if (refused.empty() && report.stop == StopReason::Unchanged) refused = report.refusedBecause;
  if (!refused.empty()) {
    report.refusedBecause = refused;
    report.regionEnergyAfter = report.regionEnergyBefore;
    report.keptStage = -1;
    report.stop = StopReason::Unchanged;
    report.regionFaces = FaceSet::fromFlags(selection).faces;
    return report;
  }
  report.regionFaces = splice(mesh, *piece, result, resultSelection);
  return report;
}

}  // namespace elastica
