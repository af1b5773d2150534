// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/hole_filling.h>
#include <elastica/mesh_quality.h>
#include <elastica/vertex_fans.h>
#include "flow/fair_masked.h"
#include "mesh/self_intersection.h"
#include "restoration/biharmonic_embedding.h"
#include "restoration/hole_boundary.h"
#include "restoration/hole_pinches.h"
#include "restoration/hole_triangulation.h"
#include "restoration/patch_angles.h"
#include "restoration/patch_measure.h"
#include "restoration/patch_refinement.h"
#include "mesh/patch_remeshing.h"
#include "restoration/rim_rule.h"
#include "mesh/submesh.h"
#include "mesh/tangential_relaxation.h"
#include "support/parallel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <unordered_set>

namespace elastica {
namespace {

// Face-rings around the hole's border handed to the flow: the first gives the border vertices
// (the first fixed ring, where H is evaluated) their complete fans, the second gives them to
// their neighbours (the second fixed ring, whose H enters the energy). A third ring, once kept as
// a margin, only entered the mean edge length that scales the step and the tolerances (sphere
// caps of 40–120° ended with the same energies to 6 digits, but for the 90° one) and cost a sixth
// of the bunny-flank fill's time.
constexpr int kFlowRings = 2;
// The flow's knobs for a patch, beside HoleFillOptions::flow (flow/internal_flow_options.h).
constexpr InternalFlowOptions kPatchFlow{
    // Flips every fifth accepted step: a 406-edge hole in the armadillo (refined once) filled in
    // 1.33 s instead of 1.88 s, ending at the same energy (102.756 against 102.757) and angle (25.1°).
    /*flipInterval=*/5,
    // The bi-Laplace start is smooth already: growing τ from the mesh's scale would only ramp up.
    /*startAtShapeScale=*/true,
    // A patch may move 10 edge lengths a step (fair: 2): a 406-edge hole in the armadillo (refined
    // once) took 12 steps instead of 36, 0.84 s instead of 1.30 s, to E 102.547 (102.545).
    /*maxJump=*/10,
    // A step too long is shortened, not rejected: a rejection cost a factorisation and slowed τ's growth.
    /*shortenJumps=*/true};
// A patch whose smallest angle is below this after the flow is remeshed and flowed again (the
// 25° target; it was 30° before the border ring's own stage, patch_angles, which now lifts most
// patches above 25° and leaves the second flow, half a fill's time, to the rest).
constexpr double kRemeshBelowDegrees = 25;
// A bi-Laplace start whose smallest angle is below this is remeshed before the flow. Above it the
// flow, its edge flips and patch_angles do better from the refinement's own triangles: remeshing
// the bunny-flank start (24°) cost 4 ms, twice the rest of the flow, and ended at 31.5° instead of
// 32.8°; a 200-edge hole in a 44k-vertex scan (start 14°) spent 40 % of its fill remeshing, and
// ended at 34.8° with it (and 40 % slower), 32.1° without.
constexpr double kRemeshStartBelowDegrees = 10;  // a 110° cap starts at 5°; from there the flow folds it
// The angle every patch face should reach (issue 15): a stage may lower the patch's smallest angle
// only down to this, or to what it was given if that was already lower.
constexpr double kTargetAngleDegrees = 25;
// A stage may raise the patch's energy by this much (relative) and still count as no worse: the
// flow's own step acceptance (semi_implicit_integrator.cpp) allows the same.
constexpr double kEnergySlack = 1e-4;
// A coarse-to-fine fill (HoleFillOptions::coarseFirstFromEdges) first works at this many times the
// border's edge lengths: a quarter of the vertices.
constexpr double kCoarseScale = 2;
// The fine patch of a coarse-to-fine fill is remeshed to this many times the border's edge lengths
// inside, ramping down to the border's own lengths over kFineRampRings rings of the coarse patch.
// A patch refined directly from the triangulation has mean edges of 1.15–1.44 times the border's
// (CGAL's 1.22–1.37): remeshing the fine patch to 1.0 made twice CGAL's vertices and the fine flow
// most of the fill's time. Measured (fill_profile, CPU of one fill, on a loaded machine) at 1.0 →
// 1.22 → 1.3: the armadillo's 1,978-edge hole 22.1 → 15.5 → 13.9 s (184,488 → 126,288 → 111,787
// new vertices; 25.4°, 25.2°, 25.4°, the border allows 25.4°), the bunny's 792-edge hole 4.3 → 2.6
// → 2.2 s (28.8°, 29.1°, 29.9°). Without the ramp (the same length up to the border) the
// armadillo's patch ended at 23.3° (1.22) and 23.7° (1.3): border edges of 1.0 against a first row
// at 1.22–1.3 leave the border ring's faces uneven, and the last angle pass does not lift them.
constexpr double kFineScale = 1.3;
constexpr double kFineRampRings = 2;
// Each hole is restored with OpenMP's regions on one thread (SerialRegions). Its flow, remeshing
// and measures are many parallel regions of little work each, and libgomp's threads spin between
// them: on the 2-core machine with other jobs running (load 4-6), the bunny's 408-edge hole
// (refined once, a 5,800-vertex patch) took 2.5 s on two threads and 0.9 s on one (the same with
// OMP_WAIT_POLICY=passive), and the armadillo's 1,978-edge hole (a 184,000-vertex patch) 45.2 s
// against 37.4 s, and 32.9 s against 24.9 s in restoration_sweep (CGAL 5.5 and 5.7 s). On an idle
// machine two threads had shortened that hole's remeshing (5.7 → 4.5 s). The patches are also the
// same on any number of cores (parallel sums group their terms by thread).

// The remeshing of a patch about to be flowed, toward `lengthScale` times the border's edge
// lengths: half the rounds of a full one, since patch_angles and the flow's flips finish the job
// (a 6,000-vertex patch spent 0.9 s, more than its flow, in ten rounds).
PatchRemeshingOptions remeshingBeforeAFlow(double lengthScale) {
  PatchRemeshingOptions rounds;
  rounds.iterations = rounds.relaxPasses = 5;
  rounds.lengthScale = lengthScale;
  return rounds;
}

// The smallest angle of the patch faces away from the border: those without a border edge (two
// corners before `firstNew`). The faces on border edges are the border ring's, which remeshing
// leaves to patch_angles.
double smallestAngleAwayFromBorder(const TriMesh& sub, const std::vector<std::uint8_t>& patchFace, int firstNew) {
  double best = 180;
  for (int f = 0; f < sub.faceCount(); ++f) {
    if (!patchFace[f]) continue;
    const Face& t = sub.faces[f];
    if ((t[0] < firstNew) + (t[1] < firstNew) + (t[2] < firstNew) >= 2) continue;
    best = std::min(best, smallestAngleDegrees(sub.positions[t[0]], sub.positions[t[1]], sub.positions[t[2]]));
  }
  return best;
}

// Scales the `sigma` of the patch vertices (from `firstNew` on) by `scale`, ramping from 1 on the
// first ring inside the border to `scale` at kFineRampRings + 1 rings and beyond (rings counted
// along the patch's edges), so that a remeshing to `sigma` keeps the border's density along the
// border and coarsens the inside.
void coarsenAwayFromBorder(const TriMesh& sub, const std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma,
                           int firstNew, double scale) {
  const int nv = sub.vertexCount();
  std::vector<std::vector<int>> neighbours(nv);
  for (int f = 0; f < sub.faceCount(); ++f) {
    if (!patchFace[f]) continue;
    const Face& t = sub.faces[f];
    for (int k = 0; k < 3; ++k) {
      neighbours[t[k]].push_back(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].push_back(t[k]);
    }
  }
  std::vector<int> ring(nv, -1), queue;
  for (int v = 0; v < firstNew; ++v)
    if (!neighbours[v].empty()) {
      ring[v] = 0;
      queue.push_back(v);
    }
  for (std::size_t q = 0; q < queue.size(); ++q)
    for (int w : neighbours[queue[q]])
      if (ring[w] < 0) {
        ring[w] = ring[queue[q]] + 1;
        queue.push_back(w);
      }
  for (int v = firstNew; v < nv; ++v) {
    const double along = ring[v] < 0 ? 1 : std::clamp((ring[v] - 1) / kFineRampRings, 0.0, 1.0);
    sigma[v] *= 1 + (scale - 1) * along;
  }
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// Mean length of the mesh edges at `v` (whose faces are `faces`): the density a patch must match
// there. Summed over the neighbours in increasing order, as a Topology's one-ring lists them.
double borderEdgeLength(const TriMesh& mesh, VertexFaces::FaceRange faces, int v) {
  std::vector<int> ring;
  for (int f : faces)
    for (int x : mesh.faces[f])
      if (x != v) ring.push_back(x);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  double sum = 0;
  for (int x : ring) sum += (mesh.positions[x] - mesh.positions[v]).norm();
  return sum / std::max(static_cast<int>(ring.size()), 1);
}

// The flow's step and time limits hold for the whole fill: each hole's flow gets what the work
// before it left (a limit already used up stops the flow at once; it keeps the bi-Laplace patch).
FlowOptions remainingFlowBudget(const FlowOptions& flow, long long stepsUsed, double secondsUsed) {
  FlowOptions f = flow;
  f.maxSteps = std::max<long long>(flow.maxSteps - stepsUsed, 0);
  if (flow.maxSeconds > 0) f.maxSeconds = std::max(flow.maxSeconds - secondsUsed, 1e-9);  // 0 would mean none
  return f;
}

// The patch as one stage left it, and how good it is.
struct PatchSnapshot {
  TriMesh sub;
  std::vector<std::uint8_t> patchFace;
  std::vector<double> sigma;
  PatchMeasure measure;
};

// The pipeline after the triangulation, one stage at a time: each stage is measured on the same
// region (restoration/patch_measure.h) and kept only if it does not lower the smallest angle below
// min(the last kept stage's, kTargetAngleDegrees) and does not raise the energy. The next stage
// goes on from what the last one left, kept or not (a remeshing raises the discrete energy, the
// flow after it lowers it below where it was: judged one by one, neither would run), and the fill
// ends with the last kept patch. A fill is then never worse than its own start (a small hole's full
// fill once ended at 12° and E 8.2 → 20.8 from a bi-Laplace start with 23.5°).
class MonotonePatch {
 public:
  MonotonePatch(TriMesh& sub, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, HoleReport& hole)
      : sub_(sub), patchFace_(patchFace), sigma_(sigma), hole_(hole) {
    kept_ = {sub_, patchFace_, sigma_, measurePatch(sub_, patchFace_)};
    keptCrosses_ = selfIntersects(sub_, &patchFace_);
    record("triangulation", true, kept_.measure, 0);
  }

  // Judges what the current stage left: true if it is kept (the new best). `energy` false judges
  // the angle only: the triangulation's energy is not comparable with a patch that has vertices
  // inside (its fan puts all the bending into a few border vertices with coarse areas, and the
  // discrete energy of a crease grows as it is sampled finer: CGAL's elephant has 15-edge holes
  // whose flat fan reads lower than any smooth patch).
  // `energyFrom`: the energy to compare with instead of the kept stage's, for a stage that starts
  // from a patch of another resolution (the discrete energy of a coarser patch reads lower for the
  // same surface: a 70° cap flowed at twice the edge length, 8.72, against 8.78 fine).
  bool judge(const char* stage, long long steps, std::string why = "", bool energy = true,
             std::optional<double> energyFrom = std::nullopt) {
    if (!why.empty()) {  // the stage failed: what it left is not a patch to go on from
      restore();
      record(stage, false, kept_.measure, steps, why);
      return false;
    }
    const PatchMeasure m = measurePatch(sub_, patchFace_);
    const PatchMeasure& before = kept_.measure;
    const bool lowerAngle = m.minAngleDegrees < std::min(before.minAngleDegrees, kTargetAngleDegrees) - 1e-9;
    const double reference = std::max(energyFrom.value_or(before.energy), flatAtPatchResolution_.value_or(-HUGE_VAL));
    const bool higherEnergy = energy && !(m.energy <= reference + kEnergySlack * std::max(std::abs(reference), 1.0));
    // Faces that cross (the patch through itself or its surroundings within the piece) undo a
    // stage too: the fill's flow runs without the fairing's embedding guard.
    // (Only where the kept patch is free of crossings itself: a border that runs through the
    // surface around it makes every patch cross, and then no stage can be judged by it.)
    const bool crossing = !lowerAngle && !higherEnergy && !keptCrosses_ && selfIntersects(sub_, &patchFace_);
    const bool keep = !lowerAngle && !higherEnergy && !crossing;
    if (keep) {
      kept_ = {sub_, patchFace_, sigma_, m};
      triangulationKept_ = false;
      if (m.minAngleDegrees >= kTargetAngleDegrees) flatAtPatchResolution_.reset();
    }
    record(stage, keep, m, steps,
           keep ? "" : lowerAngle ? "smallest angle lower" : higherEnergy ? "energy higher" : "faces cross");
    return keep;
  }

  // A stage measured but judged together with the next one (refinement samples the flat fill's
  // creases finer, which raises their discrete energy without changing the shape): judge() the
  // next, then settleWithNext() with its verdict.
  void note(const char* stage) {
    noted_ = hole_.stages.size();
    record(stage, false, measurePatch(sub_, patchFace_), 0);
  }
  void settleWithNext(bool kept) {
    FillStageReport& s = hole_.stages[noted_];
    s.kept = kept;
    s.why = kept ? "" : "not kept with the next stage";
  }
  // A patch with needles (below the target angle) is no energy to hold a finer patch to: a fan
  // counts each crease once, over coarse areas, and the same flat fill refined reads higher without
  // changing shape (a 21-edge hole in CGAL's dino: 26.6 against 41.9), so every flow was undone
  // there and the needles stayed. From a triangulation with needles on, and while the patch kept
  // has needles, a stage is judged against the larger of the kept patch's energy and the flat
  // fill's at the refined resolution (`energy`), the start it must still beat.
  void judgeAgainstTheRefinedFill(double energy) {
    if (kept_.measure.minAngleDegrees < kTargetAngleDegrees) flatAtPatchResolution_ = energy;
  }
  // The energy the next stage is judged against (the report's energy before the flow).
  double reference() const { return std::max(kept_.measure.energy, flatAtPatchResolution_.value_or(-HUGE_VAL)); }
  // True while no stage after the triangulation has been kept.
  bool triangulationKept() const { return triangulationKept_; }
  // Ends with the last kept patch.
  void restore() {
    sub_ = kept_.sub;
    patchFace_ = kept_.patchFace;
    sigma_ = kept_.sigma;
  }
  const PatchMeasure& kept() const { return kept_.measure; }

 private:
  void record(const char* stage, bool kept, const PatchMeasure& m, long long steps, std::string why = "") {
    hole_.stages.push_back({stage, kept, m.minAngleDegrees, m.energy, steps, seconds(last_), std::move(why)});
    last_ = std::chrono::steady_clock::now();
  }

  TriMesh& sub_;
  std::vector<std::uint8_t>& patchFace_;
  std::vector<double>& sigma_;
  HoleReport& hole_;
  PatchSnapshot kept_;
  bool keptCrosses_ = false;
  bool triangulationKept_ = true;
  std::optional<double> flatAtPatchResolution_;  // judgeAgainstTheRefinedFill's, while the kept patch has needles
  std::size_t noted_ = 0;  // the stage note() recorded
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// A patch is "converged" only if a flow of it ran, converged and was kept: a patch no flow moved
// (no vertex inside, a stage list that ends before the flow) or whose every flow was undone is
// "unchanged" by the flow, and the reason says which.
void settleStop(HoleReport& hole, bool innerVertices) {
  if (hole.stop != StopReason::Converged) return;  // a limit or a divergence says so itself
  bool flowed = false, flowKept = false;
  for (const FillStageReport& s : hole.stages) {
    if (s.stage.find("flow") == std::string::npos) continue;
    flowed = true;
    flowKept = flowKept || s.kept;
  }
  if (flowKept) return;
  hole.stop = StopReason::Unchanged;
  if (!hole.reason.empty()) return;
  double smallest = 180;  // of the patch kept
  for (const FillStageReport& s : hole.stages)
    if (s.kept) smallest = s.minAngleDegrees;
  char angle[64];
  std::snprintf(angle, sizeof angle, "%.1f", smallest);
  if (flowed)
    hole.reason = "every flow of the patch was undone (it lowered the smallest angle or raised the energy)";
  else if (!innerVertices && smallest < kTargetAngleDegrees)  // a fan with needles: say why it stays
    hole.reason = std::string("a flat patch with no vertex inside (the border's edge lengths asked for none), smallest "
                              "angle ") + angle + "°: no flow can bend it";
}

// The vertices of `sub` free to move: the patch's own, from `firstNew` on.
std::vector<std::uint8_t> freeVertices(const TriMesh& sub, int firstNew) {
  std::vector<std::uint8_t> free(sub.positions.size(), 0);
  std::fill(free.begin() + firstNew, free.end(), 1);
  return free;
}

// A small hole: the triangulation is its patch, and the refinement's Delaunay flips and ours are
// all that change it. Judged on the angle alone: a patch without a vertex inside cannot bend,
// its flips trade one crease for another, and the minimum-weight triangulation is the one with
// the smallest creases (on CGAL's elephant every flip raised the energy, and keeping them out
// left 6-edge holes at 5°).
void restoreFan(TriMesh& sub, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
                MonotonePatch& patch) {
  patch.judge("refinement", 0, "", false);
  if (improvePatchAngles(sub, patchFace, sigma, firstNew) > 0) patch.judge("flips", 0, "", false);
  patch.restore();
}

// Embeds the refined patch by the bi-Laplace solve; the error's text if the solve failed.
std::string embedPatch(TriMesh& sub, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
                       const PatchRefinementOptions& refinement) {
  try {
    solveBiharmonic(sub, freeVertices(sub, firstNew));
    // The embedded patch is larger than the flat fill where the hole is deep: refine where it
    // stretched, and solve again.
    const int before = sub.vertexCount();
    refinePatch(sub, patchFace, sigma, refinement);
    if (sub.vertexCount() > before) solveBiharmonic(sub, freeVertices(sub, firstNew));
  } catch (const NumericalError& e) {
    return std::string(e.what()) + "; kept the flat patch";
  }
  return "";
}

// The flow stages of one patch. Budgets (steps, seconds) are shared by all stages of all holes.
class PatchFlow {
 public:
  PatchFlow(TriMesh& sub, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
            const FlowOptions& flowBudget, MonotonePatch& patch, HoleReport& hole)
      : sub_(sub), patchFace_(patchFace), sigma_(sigma), firstNew_(firstNew), flow_(flowBudget), patch_(patch), hole_(hole) {
    flow_.boundary = BoundaryMode::Fixed;
  }

  // One flow stage: what `prepare` does to the patch, then its angles raised where the border
  // ring is poor, then the flow, judged (against `energyFrom` if given). True if kept.
  template <class Prepare>
  bool stage(const char* name, Prepare prepare, std::optional<double> energyFrom = std::nullopt) {
    const auto began = std::chrono::steady_clock::now();
    prepare();
    // Only a patch below the target: moving the vertices of one that reaches it already (toward a
    // 35° margin, within their tangent planes) changes the surface the flow starts from, and the
    // flow, which moves vertices along their normals, ends elsewhere (the armadillo's 20-edge hole:
    // 0.052 % from the removed surface with the pass, 0.048 % without, CGAL's 0.047 %; same 27.1°).
    // What the flow lowers below the target, the pass after it raises.
    if (smallestAngleDegrees(sub_, patchFace_) < kTargetAngleDegrees) improvePatchAngles(sub_, patchFace_, sigma_, firstNew_);
    std::string why;
    long long steps = 0;
    flowOnce(steps, why);
    hole_.steps += steps;
    flow_.maxSteps = std::max<long long>(flow_.maxSteps - steps, 0);
    if (flow_.maxSeconds > 0) flow_.maxSeconds = std::max(flow_.maxSeconds - seconds(began), 1e-9);  // 0 would mean none
    const bool kept = patch_.judge(name, steps, why, true, energyFrom);
    if (!why.empty()) hole_.reason = why + "; kept the patch of the last stage kept";
    return kept;
  }

  // Tangential relaxation of the patch's vertices (a stage's `prepare`).
  void relax() { relaxTangentially(sub_, freeVertices(sub_, firstNew_)); }

 private:
  // The flow, then the angles below the target raised: its `steps`, and in `why` what stopped it
  // if it failed.
  void flowOnce(long long& steps, std::string& why) {
    try {
      const FlowReport r = fairMasked(sub_, &patchFace_, flow_, kPatchFlow);
      steps = r.steps;
      hole_.stop = r.stop;
      // After the flow only what is below the target: moving vertices that are fine already
      // undoes the flow's work (a small hole on CGAL's elephant went from E 20.2 to 23.8).
      if (smallestAngleDegrees(sub_, patchFace_) < kTargetAngleDegrees)
        improvePatchAngles(sub_, patchFace_, sigma_, firstNew_, kTargetAngleDegrees, 8, true);
    } catch (const FlowDivergedError& e) {
      steps = e.report().steps;
      hole_.stop = StopReason::Diverged;
      why = e.what();
    } catch (const Error& e) {  // e.g. a sliver that makes the explicit step vanish
      why = e.what();
    }
  }

  TriMesh& sub_;
  std::vector<std::uint8_t>& patchFace_;
  std::vector<double>& sigma_;
  int firstNew_;
  FlowOptions flow_;
  MonotonePatch& patch_;
  HoleReport& hole_;
};

// The flow stages after the bi-Laplace start, each judged; the patch ends as the last stage left
// it (restorePatch then takes the last kept). `lengthScale`: the coarse start's edge lengths.
void flowPatch(TriMesh& sub, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
               const FlowOptions& flowBudget, bool coarseFirst, double lengthScale, MonotonePatch& patch, HoleReport& hole) {
  PatchFlow flow(sub, patchFace, sigma, firstNew, flowBudget, patch, hole);
  // The bi-Laplace patch is stretched unevenly where the hole is deep (smallest angle 5° on a
  // 110° cap): remesh it toward the border's edge lengths before the flow moves it, where it has
  // slivers. Judged like any stage; the flow goes on from it either way (from the slivers, the
  // flow folded the patch of a 110° cap through itself).
  if (patch.kept().minAngleDegrees < kRemeshStartBelowDegrees) {
    remeshPatch(sub, patchFace, sigma, firstNew, remeshingBeforeAFlow(lengthScale));
    patch.judge("remeshing", 0);
  }
  auto relax = [&] { flow.relax(); };
  // A step or time limit (or the caller's cancel) ended the last flow: no further stage.
  auto limitReached = [&] { return stoppedAtALimit(hole.stop); };
  std::optional<double> fineStart;
  if (coarseFirst) {
    // The coarse patch's flow, judged like any stage; the fine one goes on from what it left,
    // remeshed to the border's density (judged with the flow after it, as the first refinement
    // is: its new vertices lie on the coarse patch's flat faces, which the flow rounds off).
    // Remeshed rather than refined at centroids: refinement leaves the coarse border ring's faces
    // as they are (the armadillo's 1,978-edge hole kept a 17.4° face on a border edge, and a
    // second remeshing and flow took 42 s), remeshing makes them anew.
    flow.stage("coarse flow", relax);
    if (limitReached()) return;
    coarsenAwayFromBorder(sub, patchFace, sigma, firstNew, kFineScale);
    remeshPatch(sub, patchFace, sigma, firstNew, remeshingBeforeAFlow(1.0));
    patch.note("remeshing to the border's density");
    fineStart = hole.stages.back().energy;
  }
  // After a coarse flow, the fine flow is judged against its own start (the energy of the remeshed
  // patch) and, failing, leaves the coarse patch.
  const bool flowKept = flow.stage("flow", relax, fineStart);
  if (coarseFirst) patch.settleWithNext(flowKept);
  // The flow inflates a deep patch (a 120° cap's bi-Laplace patch has 40 % of the restored cap's
  // area) and so stretches the triangles it started from: remesh at the final size, and flow
  // again from there (a short run: the shape is already there). Not where the only thin faces
  // are on border edges: remeshing keeps the border and leaves them as they are (a 794-edge hole
  // in the armadillo spent 5 s, half its fill, to go from 17.4° to 17.5°).
  const bool thinInside = !flowKept || smallestAngleAwayFromBorder(sub, patchFace, firstNew) < kRemeshBelowDegrees;
  if (!limitReached() && thinInside && patch.kept().minAngleDegrees < kRemeshBelowDegrees)
    flow.stage("remeshing and flow", [&] { remeshPatch(sub, patchFace, sigma, firstNew); });
}

// Refines, embeds and fairs the patch (the faces flagged in `patchFace`) of `sub`, a piece of the
// mesh around one hole. The vertices from `firstNew` on are the patch's own; nothing else moves.
void restorePatch(TriMesh& sub, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
                  const HoleFillOptions& opt, const FlowOptions& flowBudget, HoleReport& hole) {
  MonotonePatch patch(sub, patchFace, sigma, hole);
  // Coarse to fine (HoleFillOptions::coarseFirstFromEdges): everything up to the first flow at
  // kCoarseScale times the border's edge lengths.
  const bool coarseFirst = opt.coarseFirstFromEdges > 0 && hole.borderEdges >= opt.coarseFirstFromEdges &&
                           opt.stopAfter == FillStage::Flow;
  const double lengthScale = coarseFirst ? kCoarseScale : 1.0;
  PatchRefinementOptions refinement = opt.refinement;
  refinement.density /= lengthScale;
  refinePatchOrItsFan(sub, patchFace, sigma, refinement, std::min(kTargetAngleDegrees, hole.borderBoundDegrees));
  if (opt.stopAfter == FillStage::Refinement) return;
  if (sub.vertexCount() == firstNew) {
    restoreFan(sub, patchFace, sigma, firstNew, patch);
    return;
  }
  patch.note("refinement");
  patch.judgeAgainstTheRefinedFill(hole.stages.back().energy);
  const std::string failed = embedPatch(sub, patchFace, sigma, firstNew, refinement);
  if (!failed.empty()) hole.reason = failed;
  const bool start = patch.judge("bi-Laplace", 0, failed, false);
  patch.settleWithNext(start);
  hole.energyBefore = hole.energyAfter = patch.reference();
  // A start judged worse than the flat fill (a sliver of 0.3° where the fill had 0.4°, on a
  // 200-edge hole in the elephant) is still the shape to go on from: the remeshing and the flow
  // after it are judged against the flat fill, which stays the patch if they do no better.
  if (failed.empty() && opt.stopAfter != FillStage::Biharmonic)
    flowPatch(sub, patchFace, sigma, firstNew, flowBudget, coarseFirst, lengthScale, patch, hole);
  // Ends with the last kept patch; where that is still the triangulation, nothing was gained.
  patch.restore();
  hole.energyAfter = patch.kept().energy;
  if (patch.triangulationKept()) hole.energyBefore = hole.energyAfter;
}

// Welds `removed` into `kept` (two copies of one point on a hole border) unless an edge would then
// have more than two faces. `adjacency` follows.
bool weldCopies(AppendedMesh& mesh, VertexFaces& adjacency, int kept, int removed) {
  auto facesOnEdge = [&](int a, int b) {
    int count = 0;
    for (int f : adjacency.faces(a)) {
      const Face& t = mesh.face(f);
      count += t[0] == b || t[1] == b || t[2] == b;
    }
    return count;
  };
  for (int f : adjacency.faces(removed)) {
    for (int x : mesh.face(f)) {
      if (x == removed) continue;
      if (x == kept) return false;  // an edge between the copies: a face would lose its area
      if (facesOnEdge(kept, x) + facesOnEdge(removed, x) > 2) return false;
    }
  }
  // A corner keeps its number: the face's slot that held `removed` now holds `kept`.
  const VertexFaces::CornerRange removedCorners = adjacency.corners(removed);
  const std::vector<int> moved(removedCorners.begin(), removedCorners.end());
  std::vector<int>& keptCorners = adjacency.edit(kept);
  for (int c : moved) {
    mesh.face(c / 3)[c % 3] = kept;
    keptCorners.push_back(c);
  }
  adjacency.edit(removed).clear();
  return true;
}

// The faces around `v` grouped into fans (faces joined across an edge at v), each in face order.
std::vector<std::vector<int>> fansAround(const TriMesh& mesh, std::vector<int> faces, int v) {
  std::sort(faces.begin(), faces.end());
  std::vector<int> corners, fan;
  for (int f : faces) corners.push_back(cornerAt(f, mesh.faces[f], v));
  FanScratch scratch;
  std::vector<std::vector<int>> fans(fansAt(mesh.faces, corners.data(), corners.size(), fan, scratch));
  for (std::size_t i = 0; i < faces.size(); ++i) fans[fan[i]].push_back(faces[i]);
  return fans;
}

// A weld as made: the faces the removed copy had then, and those the kept vertex had before its
// first weld.
struct WeldRecord {
  PinchWeld weld;
  std::vector<int> removedFaces, keptFaces;
};

// After filling (`mesh` holds the patches; `facesAt` lists the faces at each kept vertex): where
// the patches did not join a copy's fan to the kept vertex's own faces (its holes stayed open),
// that fan gets its copy back. The copies still unused are then dropped (later vertices move down).
// Returns the welds that stand. Allocates everything before it renumbers: once it has begun to
// move vertices, it cannot throw.
std::vector<PinchWeld> settleWelds(TriMesh& mesh, const std::map<int, std::vector<int>>& facesAt, const std::vector<WeldRecord>& welds) {
  std::vector<PinchWeld> standing;
  std::vector<std::vector<int>> fans;
  int fansOf = -1;
  std::vector<char> fanTaken;
  for (const WeldRecord& w : welds) {
    const int p = w.weld.kept, q = w.weld.removed;
    if (fansOf != p) {
      fans = fansAround(mesh, facesAt.at(p), p);
      fansOf = p;
      fanTaken.assign(fans.size(), 0);
    }
    auto fanOf = [&](int face) {
      for (std::size_t k = 0; k < fans.size(); ++k)
        if (std::find(fans[k].begin(), fans[k].end(), face) != fans[k].end()) return k;
      return fans.size();
    };
    const std::size_t fan = fanOf(w.removedFaces.front());
    const bool joined = std::any_of(w.keptFaces.begin(), w.keptFaces.end(), [&](int f) { return fanOf(f) == fan; });
    if (joined || fan == fans.size() || fanTaken[fan]) {  // taken: joined to an earlier copy, which stays
      standing.push_back(w.weld);
      continue;
    }
    fanTaken[fan] = 1;
    for (int f : fans[fan])
      for (int& x : mesh.faces[f]) x = x == p ? q : x;
  }
  if (standing.empty()) return standing;
  std::vector<char> drop(mesh.positions.size(), 0);
  for (const PinchWeld& w : standing) drop[w.removed] = 1;
  std::vector<int> newIndex(mesh.positions.size(), -1);
  int next = 0;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (drop[i]) continue;
    newIndex[i] = next;
    mesh.positions[next++] = mesh.positions[i];
  }
  mesh.positions.resize(next);
  for (Face& t : mesh.faces)
    for (int& x : t) x = newIndex[x];
  return standing;
}

// The smallest angle of the faces from `firstFace` on.
double smallestAngleSince(const AppendedMesh& mesh, int firstFace) {
  double best = 180;
  for (int f = firstFace; f < mesh.faceCount(); ++f) {
    const Face& t = mesh.face(f);
    best = std::min(best, smallestAngleDegrees(mesh.position(t[0]), mesh.position(t[1]), mesh.position(t[2])));
  }
  return best;
}

void validate(const HoleFillOptions& opt) {
  if (opt.maxHoleEdges < 3) throw InvalidInputError("fill: the largest hole to fill must have at least 3 border edges");
  if (!(opt.refinement.density > 0)) throw InvalidInputError("fill: the refinement density must be > 0");
  if (opt.flow.subdivisionLevels != 0)
    throw InvalidInputError("fill: subdivision is not available when filling holes (it would split the original faces)");
}

// What the patches need of the mesh as it was given, at each border vertex: the mean length of
// its edges (the density to match) and the angle its faces span (the border's corner bound).
struct BorderVertex {
  double edgeLength, meshAngle;
};
using BorderVertices = std::unordered_map<int, BorderVertex>;

BorderVertices borderVerticesOf(const TriMesh& mesh, const VertexFaces& adjacency, const std::vector<HoleHalfEdge>& halfEdges) {
  BorderVertices border;
  for (const HoleHalfEdge& h : halfEdges)
    for (int v : {h.from, h.to})
      if (border.find(v) == border.end())
        border.emplace(v, BorderVertex{borderEdgeLength(mesh, adjacency.faces(v), v), cornerAngleSum(mesh, adjacency.faces(v), v)});
  return border;
}

// The hole loops, split where a border touches itself and its copies of the point were welded
// (`welds`, each rewired face's value before its first change into `weldedFaces`).
std::vector<HoleLoop> weldPinches(const TriMesh& output, AppendedMesh& mesh, VertexFaces& adjacency,
                                  std::vector<HoleHalfEdge> halfEdges, std::vector<WeldRecord>& welds,
                                  std::unordered_map<int, Face>& weldedFaces) {
  std::vector<HoleLoop> loops;
  for (const HoleLoop& found : findHoleLoops(std::move(halfEdges))) {
    PinchSplit split = splitAtPinches(found, output.positions, [&](int kept, int removed) {
      WeldRecord w{{kept, removed}, adjacency.faces(removed).copy(), adjacency.faces(kept).copy()};
      for (const WeldRecord& earlier : welds)
        if (earlier.weld.kept == kept) w.keptFaces = earlier.keptFaces;
      for (int f : w.removedFaces) weldedFaces.emplace(f, output.faces[f]);
      if (!weldCopies(mesh, adjacency, kept, removed)) return false;
      welds.push_back(std::move(w));
      return true;
    });
    for (HoleLoop& loop : split.loops) loops.push_back(std::move(loop));
  }
  return loops;
}

// An island (a fragment inside a hole, bounded by its own loop) leaves both loops open: a disc
// across the hole would cross the island, and one across the island's loop would close the
// island onto itself. The report says so; the user removes the fragment (or keeps the hole).
// Returns, for each loop, why it stays open for an island (empty: no island).
std::vector<std::string> islandReasons(const TriMesh& output, const VertexFaces& adjacency, const std::vector<HoleLoop>& loops) {
  std::vector<std::string> islandReason(loops.size());
  const std::vector<int> islandOf = islandsInHoles(output, adjacency, loops);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (islandOf[i] < 0) continue;
    const HoleLoop& hole = loops[islandOf[i]];
    islandReason[i] = "the border of an island of faces (a separate piece) inside a hole of " + std::to_string(hole.edgeCount()) +
                      " border edges: left open with that hole";
    if (islandReason[islandOf[i]].empty())
      islandReason[islandOf[i]] = "an island of faces (a separate piece with a border of " + std::to_string(loops[i].edgeCount()) +
                                  " edges) lies inside it, which a patch would cross: left open";
  }
  return islandReason;
}

// Why `loop` is left open before any triangulation is tried (empty: it is filled); sets `hole.rim`
// once the loop gets as far as the rim rule.
std::string whyLeftOpen(const HoleLoop& loop, const HoleFillOptions& opt, const std::string& islandReason,
                        const RimMeasure& rim, HoleReport& hole) {
  if (loop.edgeCount() > opt.maxHoleEdges)
    return "larger than the limit of " + std::to_string(opt.maxHoleEdges) + " border edges";
  if (loop.pinched) return "its border touches itself at a vertex";
  if (!islandReason.empty()) return islandReason;
  hole.rim = rim.rim;
  if (!hole.rim || opt.closeRims) return "";
  char why[200];
  std::snprintf(why, sizeof why,
                "the outer rim of an open surface (it turns by %+.0f deg like an outline and spans %.0f %% of its "
                "piece's area): left open; close rims to fill it",
                rim.turning * 180 / M_PI, 100 * rim.areaRatio);
  return why;
}

// Writes the restored patch of `sub` (its faces flagged in `patchFace`; vertices from
// `subVertices` on and faces from `subFaces` on are new) back into `mesh`, whose patch began at
// `firstVertex` and `firstFace`, and renews the face lists of the loop's vertices.
void writePatchBack(AppendedMesh& mesh, VertexFaces& adjacency, const Submesh& sub, const std::vector<std::uint8_t>& patchFace,
                    int subVertices, int subFaces, const HoleLoop& loop, int firstVertex, int firstFace) {
  auto global = [&](int i) { return i < subVertices ? sub.vertex[i] : firstVertex + i - subVertices; };
  for (int i = subVertices; i < sub.mesh.vertexCount(); ++i) mesh.positions.push_back(sub.mesh.positions[i]);
  for (int f = 0; f < sub.mesh.faceCount(); ++f) {
    if (!patchFace[f]) continue;
    const Face& t = sub.mesh.faces[f];
    const Face g{global(t[0]), global(t[1]), global(t[2])};
    if (f < subFaces) mesh.face(sub.face[f]) = g;
    else mesh.faces.push_back(g);
  }
  // The patch was rewired: renew the face lists of its border.
  for (int v : loop.vertices) {
    auto& corners = adjacency.edit(v);
    corners.erase(std::remove_if(corners.begin(), corners.end(), [&](int c) { return c / 3 >= firstFace; }), corners.end());
  }
  for (int f = firstFace; f < mesh.faceCount(); ++f) adjacency.addFace(f, mesh.face(f));
}

// Restores the triangulation just appended to `mesh` (from `firstVertex` and `firstFace` on) on the
// piece of the mesh around its hole, then writes the patch back. `flowSteps`: what the holes before
// used of the flow's budget, since `start`.
void restoreAroundHole(AppendedMesh& mesh, VertexFaces& adjacency, const HoleLoop& loop, const BorderVertices& border,
                       int firstVertex, int firstFace, const HoleFillOptions& opt, long long flowSteps,
                       std::chrono::steady_clock::time_point start, HoleReport& hole) {
  Submesh sub = extractSubmesh(mesh, adjacency, loop.vertices, kFlowRings);
  const int subVertices = sub.mesh.vertexCount(), subFaces = sub.mesh.faceCount();
  std::vector<std::uint8_t> patchFace(subFaces, 0);
  for (int f = 0; f < subFaces; ++f) patchFace[f] = sub.face[f] >= firstFace;
  std::vector<double> sigma(subVertices, 0);
  const std::unordered_set<int> onLoop(loop.vertices.begin(), loop.vertices.end());
  for (int i = 0; i < subVertices; ++i)
    if (onLoop.count(sub.vertex[i])) sigma[i] = border.at(sub.vertex[i]).edgeLength;
  const SerialRegions serial;
  restorePatch(sub.mesh, patchFace, sigma, subVertices, opt, remainingFlowBudget(opt.flow, flowSteps, seconds(start)), hole);
  settleStop(hole, sub.mesh.vertexCount() > subVertices);
  writePatchBack(mesh, adjacency, sub, patchFace, subVertices, subFaces, loop, firstVertex, firstFace);
}

// After the holes: appends the patches kept aside in `mesh` to `output` and settles the welds.
// `index` (the faces around each vertex) and `border` go before the mesh grows, so that they and
// the grown arrays are never held at once.
void appendPatches(TriMesh& output, AppendedMesh& mesh, std::unique_ptr<VertexFaces> index, BorderVertices& border,
                   const std::vector<WeldRecord>& welds, HoleFillReport& report) {
  // The faces at each kept copy, for settling the welds.
  std::map<int, std::vector<int>> keptFaces;
  for (const WeldRecord& w : welds) keptFaces.emplace(w.weld.kept, index->faces(w.weld.kept).copy());
  index.reset();
  border.clear();
  // One array at a time, each grown once to its exact size.
  output.positions.reserve(output.positions.size() + mesh.positions.size());
  output.positions.insert(output.positions.end(), mesh.positions.begin(), mesh.positions.end());
  std::vector<Vec3>().swap(mesh.positions);
  output.faces.reserve(output.faces.size() + mesh.faces.size());
  output.faces.insert(output.faces.end(), mesh.faces.begin(), mesh.faces.end());
  std::vector<Face>().swap(mesh.faces);
  // Settled per kept vertex, in the order the welds were made.
  std::vector<WeldRecord> byKept = welds;
  std::stable_sort(byKept.begin(), byKept.end(), [](const WeldRecord& a, const WeldRecord& b) { return a.weld.kept < b.weld.kept; });
  report.welds = settleWelds(output, keptFaces, byKept);
}

// The fill proper, after the checks: welds rewire `output`'s faces in place (each face's value
// before its first change goes to `weldedFaces`), patches are made aside and appended to `output`
// at the end, once `index` (the faces around each vertex) is no longer needed.
void fillInPlace(TriMesh& output, std::unique_ptr<VertexFaces> index, std::vector<HoleHalfEdge> halfEdges,
                 const HoleFillOptions& opt, std::chrono::steady_clock::time_point start, HoleFillReport& report,
                 std::unordered_map<int, Face>& weldedFaces) {
  VertexFaces& adjacency = *index;
  AppendedMesh mesh(output);
  BorderVertices border = borderVerticesOf(output, adjacency, halfEdges);
  auto meshAngle = [&](int v) { return border.at(v).meshAngle; };
  auto edgeExists = [&](int a, int b) {
    for (int f : adjacency.faces(a)) {
      const Face& t = mesh.face(f);
      if (t[0] == b || t[1] == b || t[2] == b) return true;
    }
    return false;
  };
  std::vector<WeldRecord> welds;
  const std::vector<HoleLoop> loops = weldPinches(output, mesh, adjacency, std::move(halfEdges), welds, weldedFaces);
  const std::vector<std::string> islandReason = islandReasons(output, adjacency, loops);
  const std::vector<RimMeasure> rims = classifyRims(output, loops, meshAngle);
  long long flowSteps = 0;  // over all holes, against opt.flow.maxSteps
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const HoleLoop& loop = loops[l];
    const auto holeStart = std::chrono::steady_clock::now();
    HoleReport hole;
    hole.borderEdges = loop.edgeCount();
    hole.borderBoundDegrees = borderCornerBoundDegrees(output.positions, loop, meshAngle);
    std::string why = whyLeftOpen(loop, opt, islandReason[l], rims[l], hole);
    std::optional<std::vector<Face>> triangles;
    if (why.empty() && !(triangles = triangulateHole(output.positions, loop, edgeExists)))
      why = "no triangulation avoids the mesh's existing edges";
    if (!why.empty()) {
      hole.reason = std::move(why);
      hole.seconds = seconds(holeStart);
      report.holes.push_back(hole);
      continue;
    }
    const int firstVertex = mesh.vertexCount(), firstFace = mesh.faceCount();
    for (const Face& t : *triangles) {
      mesh.faces.push_back(t);
      adjacency.addFace(mesh.faceCount() - 1, t);
    }
    hole.filled = true;
    if (opt.stopAfter != FillStage::Triangulation) {  // on the piece of the mesh around the hole
      restoreAroundHole(mesh, adjacency, loop, border, firstVertex, firstFace, opt, flowSteps, start, hole);
      flowSteps += hole.steps;
    }
    hole.newVertices = mesh.vertexCount() - firstVertex;
    hole.newFaces = mesh.faceCount() - firstFace;
    hole.minAngleDegrees = smallestAngleSince(mesh, firstFace);
    hole.seconds = seconds(holeStart);
    report.holes.push_back(hole);
    if (hole.stop == StopReason::Cancelled) break;  // the caller's progress callback said stop
  }
  appendPatches(output, mesh, std::move(index), border, welds, report);
}

}  // namespace

int HoleFillReport::filledCount() const {
  return static_cast<int>(std::count_if(holes.begin(), holes.end(), [](const HoleReport& h) { return h.filled; }));
}

HoleFillReport fillHoles(TriMesh& output, const HoleFillOptions& opt) {
  validate(opt);
  const auto start = std::chrono::steady_clock::now();
  // The mesh is not copied: a scan of millions of vertices would be held twice, and a whole-mesh
  // Topology takes several times its memory. One pass over the faces finds the hole borders (and
  // refuses non-manifold edges) with a vertex→faces index of a third of the mesh's bytes; each
  // patch is made on a submesh around its hole and kept aside, and all of them are appended to
  // `output` at the end. The welds rewire faces of `output` in place and are undone if anything
  // throws, so the input is then as it was.
  checkFaceIndices(output);
  const int originalVertices = output.vertexCount(), originalFaces = output.faceCount();
  HoleFillReport report;
  report.firstNewFace = originalFaces;
  auto index = std::make_unique<VertexFaces>(output.vertexCount(), output.faces);
  std::vector<HoleHalfEdge> halfEdges = boundaryHalfEdges(output, *index);
  if (halfEdges.empty()) {
    report.seconds = seconds(start);
    return report;
  }
  std::unordered_map<int, Face> weldedFaces;  // the input's faces that welds rewire, as they were
  try {
    fillInPlace(output, std::move(index), std::move(halfEdges), opt, start, report, weldedFaces);
  } catch (...) {
    // Back to the input: the appended elements go, and the welded faces get their copies back.
    output.positions.resize(originalVertices);
    output.faces.resize(originalFaces);
    for (const auto& [f, t] : weldedFaces) output.faces[f] = t;
    throw;
  }
  report.seconds = seconds(start);
  return report;
}

}  // namespace elastica
