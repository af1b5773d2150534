// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/subdivision.h>
#include "flow/fair_masked.h"
#include "flow/explicit_integrator.h"
#include "flow/flow_state.h"
#include "flow/mesh_quality_stage.h"
#include "flow/principal_part_filter.h"
#include "flow/region_guard.h"
#include "flow/resolution_check.h"
#include "flow/schedule.h"
#include "flow/semi_implicit_integrator.h"
#include "flow/vector_integrator.h"
#include "mesh/self_intersection.h"
#include "mesh/tangential_relaxation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <string>
#include <utility>

namespace elastica {
namespace {

// An energy this many times its value at the start of a stage (and at least this many times 1),
// a mean edge length changing by kSizeJump between two checks (an unstable explicit step grows
// geometrically) or by kBlowUpFactor over a stage (a too-large step drifts the scale), means the
// scheme failed.
constexpr double kBlowUpFactor = 10;
constexpr double kSizeJump = 2;
// Semi-implicit step control (docs/benchmarks.md §2 measures it): τ₀ = 0.05 ℓ⁴, ×1.5 on success, ×0.5 on rejection;
// below 1e-12 ℓ⁴ no step can lower the energy any more: the flow is at its noise floor.
constexpr double kInitialTau = 0.05, kGrow = 1.5, kShrink = 0.5, kSmallestTau = 1e-12;
// After a failed step, τ stays below kCeilingMargin × the failed size, which rises by kCeilingGrow
// per accepted step.
constexpr double kCeilingMargin = 0.8, kCeilingGrow = 1.2;
// A stage after the first starts at this fraction of the previous stage's last accepted step.
constexpr double kStageTauCarry = 0.25;
// Semi-implicit plateau: relative energy change over this many accepted steps. Subdivision is
// triggered at 100× the final tolerance (near steady state is enough before refining).
constexpr int kPlateauWindow = 10;
constexpr double kSubdivisionPlateauFactor = 100;
// An energy plateau is the shape's only if it holds at a step of at least this fraction of the
// moving region's relaxation time A²/kShapeScaleFactor; below, the plateau is the step size's
// (docs/decisions.md, "The schedule's rules").
constexpr double kPlateauScale = 1e-3;
// A step τ ≥ A²/kShapeScaleFactor relaxes the slowest bending mode of a region of area A within
// the step (τ/2 · λ ≥ 1): the first eigenvalue of Δ² on a clamped disk of area A is ≈ 1030/A²,
// so 50 leaves a 10× margin for other shapes. See FlowOptions::shapeTolerance.
constexpr double kShapeScaleFactor = 50;
// The vector scheme stops as converged when two steps in a row show normal motion that, carried
// on over the slowest mode's relaxation time, moves no vertex by more than this many mean edge
// lengths (ten times more before a refinement). A round sphere of 4,000 vertices has about 12
// edges per radius: 0.01 ℓ is under 0.1 % of it.
constexpr double kVectorShapeTolerance = 0.01;
// FlowOptions::featureSize: its flow time in at least this many steps.
constexpr double kFeatureSteps = 4;

// `knobs` come from our own code, not from a user; a bad one is refused all the same.
void validate(const FlowOptions& o, const InternalFlowOptions& knobs) {
  auto bad = [](const std::string& what) { throw InvalidInputError("fair: " + what); };
  if (!(o.stepFactor > 0)) bad("stepFactor must be > 0");
  if (!(o.driftFactor >= 0)) bad("driftFactor must be >= 0");
  if (!(o.bilaplacianStep > 0 && o.bilaplacianStep < 0.5)) bad("bilaplacianStep must be in (0, 0.5)");
  if (!(o.energyTolerance >= 0) || !(o.subdivisionTolerance >= 0) || !(o.plateauTolerance >= 0) ||
      !(o.shapeTolerance >= 0))
    bad("tolerances must be >= 0");
  if (o.subdivisionLevels < 0 || o.subdivisionLevels > 8) bad("subdivisionLevels must be in [0, 8]");
  if (!(o.targetEdgeLength >= 0)) bad("targetEdgeLength must be >= 0");
  if (o.maxSteps < 0 || !(o.maxSeconds >= 0)) bad("maxSteps and maxSeconds must be >= 0");
  if (o.checkInterval < 1) bad("checkInterval must be >= 1");
  if (knobs.flipInterval < 1) bad("flipInterval must be >= 1");
  if (!(knobs.maxJump > 0)) bad("maxJump must be > 0");
  if (o.driftPasses < 0) bad("driftPasses must be >= 0");
  if (!(o.featureSize >= 0) || !std::isfinite(o.featureSize)) bad("featureSize must be >= 0");
  if (o.featureSize > 0 && o.flow == FlowType::Bilaplacian)
    bad("featureSize needs the elastica or Laplacian-of-H flow (the bilaplacian's time has no length unit)");
  if (o.scheme == Scheme::SemiImplicit && o.flow == FlowType::Bilaplacian)
    bad("the bilaplacian flow has the explicit scheme only");
}

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// What one stage of the schedule shares with the whole run.
struct Run {
  const FlowOptions& opt;
  const InternalFlowOptions& internal;
  FlowReport& report;
  const StageEnded& stageEnded;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double time = 0;  // flow time
  // FlowOptions::featureSize's flow time 2 ln(100) (featureSize / 2π)⁴, in which ripples of that
  // wavelength lose 99 % of their height, or none.
  const double timeLimit = opt.featureSize > 0 ? 2 * std::log(100.0) * std::pow(opt.featureSize / (2 * M_PI), 4)
                                               : std::numeric_limits<double>::infinity();
  bool stopped = false;

  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
  // The wall-time limit as a time point, for the remeshings to check (MovingRegion::deadline);
  // none for no limit, or one beyond any run (a count of seconds the clock's ticks cannot hold).
  MovingRegion::Deadline deadline() const {
    constexpr double kBeyondAnyRun = 1e9;
    if (!(opt.maxSeconds > 0) || opt.maxSeconds > kBeyondAnyRun) return MovingRegion::Deadline::max();
    return start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(opt.maxSeconds));
  }
  // Step, wall-time and flow-time limits; true if the run must stop.
  bool limitReached() {
    if (time >= timeLimit * (1 - 1e-9)) report.stop = StopReason::FeatureSize;
    else if (report.steps >= opt.maxSteps) report.stop = StopReason::MaxSteps;
    else if (opt.maxSeconds > 0 && elapsed() >= opt.maxSeconds) report.stop = StopReason::MaxSeconds;
    else return false;
    return stopped = true;
  }
  bool timeLimited() const { return std::isfinite(timeLimit); }
  // The step the semi-implicit scheme may try under FlowOptions::featureSize: a quarter of the
  // flow time at most, and no more than what remains of it.
  double capped(double tau) const {
    return timeLimited() ? std::min({tau, timeLimit / kFeatureSteps, timeLimit - time}) : tau;
  }
  // Records a checked state (λ, energy history) and reports progress; true if the caller cancelled.
  bool record(FlowState& state, int level, double energy) {
    report.minLambda = std::min(report.minLambda, state.lambda());
    report.history.push_back({report.steps, time, elapsed(), energy});
    if (!opt.progress || opt.progress({level, report.steps, energy, state.lambda(), elapsed()})) return false;
    report.stop = StopReason::Cancelled;
    return stopped = true;
  }
};

// Adds an integrator's embedding-guard refusals to the report however a stage ends.
template <class Integrator>
struct CountCrossings {
  const Integrator& integrator;
  FlowReport& report;
  ~CountCrossings() { report.crossingRejections += integrator.crossingRejections(); }
};

// Relative energy change per unit of normalised time t/A² (A the moving region's area), the
// explicit scheme's plateau measure: independent of the model's scale and of the step size, so
// one FlowOptions::energyTolerance means the same in both schemes.
double energyRate(double energyBefore, double energyAfter, double flowTime, double area) {
  const double dtHat = flowTime / (area * area);
  return (energyBefore - energyAfter) / (std::max(std::abs(energyAfter), 1.0) * dtHat);
}

// The paper's explicit scheme until the energy-rate plateau (`tolerance`) or a limit.
StageEnd explicitStage(FlowState& state, Run& run, FlowStage& stage, double tolerance, double stageStart) {
  ExplicitIntegrator integrator;
  const FlowOptions& opt = run.opt;
  FlowReport& report = run.report;
  double energy = state.energy();
  const double blowUp = kBlowUpFactor * std::max(std::abs(energy), 1.0);
  const double startEdge = state.geometry().meanEdgeLength;
  double checkpointEdge = startEdge;
  std::vector<Vec3> checkpoint = state.mesh().positions;
  long long checkpointStep = report.steps;
  double lastEnergy = energy, lastTime = run.time;
  const double area0 = state.activeArea();

  auto diverged = [&](const std::string& what) {
    state.setPositions(checkpoint);
    report.stop = StopReason::Diverged;
    report.seconds = run.elapsed();
    stage.seconds = report.seconds - stageStart;
    report.stages.push_back(stage);
    throw FlowDivergedError("fair: the flow diverged at step " + std::to_string(report.steps) + " (" + what +
                                "); restored the state of step " + std::to_string(checkpointStep) +
                                ". Try a smaller step factor.",
                            report);
  };

  while (!run.limitReached()) {
    try {
      run.time += integrator.step(state);
    } catch (const NumericalError& e) {
      diverged(e.what());
    }
    ++report.steps;
    ++stage.steps;
    if (stage.steps % opt.checkInterval != 0) continue;

    state.maintain(area0);
    energy = state.energy();
    if (!std::isfinite(energy)) diverged("non-finite energy");
    // E is scale-invariant, so an exploding mesh can keep a moderate E: watch its size too.
    const double edge = state.geometry().meanEdgeLength;
    const double jump = edge / checkpointEdge, drift = edge / startEdge;
    // The comparison flows shrink a closed surface and collapse its thin parts (the bilaplacian
    // collapses the paper's tubes, Fig. 5; E grows as a tube thins): that is their behaviour,
    // reported as StopReason::Shrunk with the last state checked before it, not as a divergence.
    // An unstable step makes the mesh grow, which stays an error for every flow.
    const bool collapsing = energy > blowUp || !(jump > 1 / kSizeJump && drift > 1 / kBlowUpFactor);
    if (opt.flow != FlowType::Elastica && edge <= checkpointEdge && collapsing) {
      state.setPositions(checkpoint);
      report.stop = StopReason::Shrunk;
      run.stopped = true;
      return StageEnd::Settled;
    }
    if (energy > blowUp) diverged("energy rose from " + fmt(lastEnergy) + " to " + fmt(energy));
    if (!(jump < kSizeJump && jump > 1 / kSizeJump))
      diverged("the mean edge length changed by a factor " + fmt(jump) + " since the last check");
    if (!(drift < kBlowUpFactor && drift > 1 / kBlowUpFactor))
      diverged("the mean edge length changed by a factor " + fmt(drift) + " since the stage began");
    checkpointEdge = edge;
    checkpoint = state.mesh().positions;
    checkpointStep = report.steps;
    if (run.record(state, stage.level, energy)) return StageEnd::Settled;
    if (std::abs(energyRate(lastEnergy, energy, run.time - lastTime, state.activeArea())) < tolerance) return StageEnd::Settled;
    lastEnergy = energy;
    lastTime = run.time;
  }
  return StageEnd::Settled;
}

// FlowOptions::shapeTolerance: the accepted step `tau` reached the scale of the moving region and
// moved no vertex along its normal by more than the tolerance (relative to the mean edge length).
bool shapeSettled(FlowState& state, const SemiImplicitIntegrator& integrator, double tau, double tolerance) {
  if (!(tolerance > 0)) return false;
  const double area = state.activeArea();
  return tau >= area * area / kShapeScaleFactor &&
         integrator.lastNormalStep() <= tolerance * state.geometry().meanEdgeLength;
}

// The semi-implicit scheme with adaptive τ until the energy rate over the last kPlateauWindow
// accepted steps falls below `rateTolerance` (FlowOptions::energyTolerance, as the explicit
// scheme), the energy plateau (the normal steps of that window lowered E by at most
// `plateauTolerance`, relative), the shape settled (FlowOptions::shapeTolerance), no step lowers
// E any more, or a limit. MeshBound if the stage ended on a plateau at a step below
// kPlateauScale of the region's relaxation time (report.stop says Stalled): the mesh, not the
// shape, held the flow back, and the schedule may remesh and flow again.
StageEnd semiImplicitStage(FlowState& state, Run& run, FlowStage& stage, double rateTolerance,
                           double plateauTolerance, bool guardEmbedding, double& lastTau) {
  SemiImplicitIntegrator integrator;
  integrator.guardEmbedding(guardEmbedding);
  const CountCrossings<SemiImplicitIntegrator> countCrossings{integrator, run.report};
  FlowReport& report = run.report;
  const double ell = state.geometry().meanEdgeLength;
  const double ell4 = ell * ell * ell * ell;
  const double area0 = state.activeArea();
  // A later stage (after a subdivision or a remeshing) starts near its predecessor's last step:
  // its shape is nearly settled already, and growing τ again from 0.05 ℓ⁴ would cost ~15 steps.
  double tau = std::max(kInitialTau * ell4, lastTau * kStageTauCarry);
  if (run.internal.startAtShapeScale) tau = std::max(tau, area0 * area0 / (10 * kShapeScaleFactor));
  double ceiling = std::numeric_limits<double>::infinity();  // the last step size that failed, raised slowly
  // The window holds, per accepted step, the flow time and the energy the normal steps have taken
  // off so far (drift passes and edge flips excluded: they redistribute vertices, and a stop
  // rule that counted them would wait on mesh changes rather than on the shape).
  double lowered = 0;
  std::deque<std::pair<double, double>> window{{lowered, run.time}};  // (lowered so far, flow time)
  while (!run.limitReached()) {
    ++report.steps;  // attempts count against maxSteps
    tau = run.capped(tau);
    if (!integrator.tryStep(state, tau)) {
      ++report.rejectedSteps;
      ceiling = tau;
      tau *= kShrink;
      if (tau < kSmallestTau * ell4) {  // nothing lowers E any more
        report.stop = StopReason::Stalled;
        return StageEnd::Settled;
      }
      continue;
    }
    // A large step moves smooth modes freely, including the scale, which E does not see.
    state.maintain(area0);
    ++stage.steps;
    run.time += tau;
    const double accepted = tau;
    lastTau = accepted;
    // Grow, but stay below the last step that failed, probing upward slowly: a plain ×1.5 / ×0.5
    // controller settles where a third of the attempts fail (ln 1.5 / ln 3), each a wasted solve.
    // A shortened step (InternalFlowOptions::shortenJumps) went as far as a step may: a larger τ
    // would only be shortened again.
    if (!integrator.lastStepShortened()) tau = std::min(tau * kGrow, kCeilingMargin * ceiling);
    ceiling *= kCeilingGrow;
    const double energy = state.energy();
    if (run.record(state, stage.level, energy)) return StageEnd::Settled;
    if (shapeSettled(state, integrator, accepted, run.opt.shapeTolerance)) return StageEnd::Settled;
    lowered += integrator.lastEnergyDecrease();
    window.emplace_back(lowered, run.time);
    if (static_cast<int>(window.size()) <= kPlateauWindow) continue;
    const double decrease = lowered - window.front().first, timeBefore = window.front().second;
    window.pop_front();
    if (decrease <= plateauTolerance * std::max(std::abs(energy), 1.0)) {
      if (accepted >= kPlateauScale * area0 * area0 / kShapeScaleFactor) return StageEnd::Settled;
      report.stop = StopReason::Stalled;
      return StageEnd::MeshBound;
    }
    if (std::abs(energyRate(energy + decrease, energy, run.time - timeBefore, state.activeArea())) < rateTolerance) return StageEnd::Settled;
  }
  return StageEnd::Settled;
}

// largestCurvatureTimesEdge (mesh_quality_stage.h) of a flow state's free vertices, on its caches.
double largestCurvatureTimesEdge(FlowState& state) {
  const Curvature& c = state.curvature();
  return largestCurvatureTimesEdge(state.topology(), state.mesh().positions, c.H, c.K, state.roles().free);
}

// Whether a step's edge flips (FlowState::maintain) made faces cross. The step's guard has just
// tested every pair with an active face at these positions; flips rewrite faces among free vertices
// only (all of them active) and change no vertex's role, so only a pair with a flipped face can
// cross, and those alone are tested (rewrittenFacesCross): the whole region's test after every
// step with a flip was a large share of the crossing tests' time on a region (docs/decisions.md,
// "Regions"). A sliding border moved after the guard
// (BoundarySlider), so there every pair with an active face is tested again, as before.
bool flipsMadeFacesCross(const TriMesh& beforeFlips, FlowState& state) {
  const std::vector<std::uint8_t>& active = state.roles().activeFace;
  if (state.roles().slidingCount > 0) return selfIntersects(state.mesh(), &active);
  return rewrittenFacesCross(beforeFlips, state.mesh(), active);
}

// vectorStage's integrator: on a selection, damped where its model overshoots
// (VectorIntegrator::dampOvershoots): a region's stage stalled by its refusals gained nothing from
// the schedule's reflows (their remeshings left the region as it was), where a whole mesh's stall
// leads to the remeshing that frees it. On a selection, the jump limit asks whether the step
// strains the mesh (VectorIntegrator::strainJumpLimit): a region moving tens of edge lengths over
// a scan's small triangles was held to them at every step. Whole meshes keep the per-vertex limit
// (their remeshings even the triangles out). On a selection, past the shape's time, preconditioned
// L-BFGS (VectorIntegrator::quasiNewton): a region's tail at τ ≫ T lowered W by 0.05–0.5 % an
// attempt for over a hundred attempts.
void configureVectorIntegrator(VectorIntegrator& integrator, const FlowState& state, bool guardEmbedding,
                               bool withHandles, double shapeTime) {
  const bool region = !state.selection().empty();
  integrator.guardEmbedding(guardEmbedding);
  integrator.saddleStiffness(withHandles);
  integrator.dampOvershoots(region);
  integrator.strainJumpLimit(region);
  integrator.quasiNewton(region, shapeTime);
}

// vectorStage's step size τ: ×2 after a step, within kCeilingMargin of the ceiling (the last
// refused size, which rises kVectorCeilingGrow per accepted step: a refused probe costs a solve,
// and the elephant's steps near their limit were refused every third attempt at ×1.2).
struct VectorStepSize {
  static constexpr double kGrowVector = 2, kVectorCeilingGrow = 1.2, kStuckFactor = 1e-4;
  double tau;
  double ceiling = std::numeric_limits<double>::infinity();
  double lastAccepted = 0, largestTau = 0;

  // After a refusal. A probe above the last accepted step goes back to just below it; otherwise
  // halve, and from beyond T straight down to T: there every mode is relaxed within the step, and
  // a smaller τ gives the same step (joint and elk grew τ to 1e11 T and more; after a refusal the
  // elephant halved 14 times from 1.4e4 T to T, each attempt refused for the same faces). (Genus 0
  // keeps the plain ×0.5: its runs did not need it, and MeshLab's float input and the CLI's double
  // then part ways on a noisy sphere, tests/plugin/meshlabserver_test.cpp.)
  void refused(bool withHandles, double shapeTime) {
    ceiling = tau;
    if (!withHandles) tau *= kShrink;
    else tau = tau > lastAccepted && lastAccepted > 0 ? std::min(lastAccepted, kCeilingMargin * tau)
                                                      : std::min(tau * kShrink, shapeTime);
  }
  // τ fell below the smallest step, or to kStuckFactor of the stage's largest accepted step (or of
  // T, if that is smaller: after a step far beyond T, a remeshed stage's first refusals are not stuck).
  bool stuck(double ell4, double shapeTime) const {
    return tau < kSmallestTau * ell4 || tau < kStuckFactor * std::min(largestTau, shapeTime);
  }
  // After an accepted step that went `accepted` far in time.
  void acceptedStep(double accepted, bool shortened) {
    lastAccepted = tau;
    largestTau = std::max(largestTau, accepted);
    if (!shortened) tau = std::min(tau * kGrowVector, kCeilingMargin * ceiling);
    ceiling *= kVectorCeilingGrow;
  }
};

// vectorStage's neck rule: κℓ above kNeckCurvatureTimesEdge and kNeckGrowth × its reference, κℓ at
// the stage's start or, with `lowestSoFar` (the first stage on a region with handles), the lowest
// κℓ so far.
struct NeckRule {
  static constexpr double kNeckCurvatureTimesEdge = 0.6, kNeckGrowth = 1.25;
  bool lowestSoFar;
  double reference;
  bool formed(double curvatureTimesEdge) {
    if (lowestSoFar) reference = std::min(reference, curvatureTimesEdge);
    return curvatureTimesEdge > std::max(kNeckCurvatureTimesEdge, kNeckGrowth * reference);
  }
};

// Edge flips are not steps: the embedding guard judges them too (a flip on knot1's swollen tube
// once left four faces crossing), and flips that make faces cross are undone, and not made again
// for the rest of the stage (flips that cross come back).
void maintainGuarded(FlowState& state, double area0, bool guardEmbedding, TriMesh& beforeFlips) {
  const long long version = state.connectivityVersion();
  if (guardEmbedding) beforeFlips = state.mesh();
  state.maintain(area0);
  if (guardEmbedding && state.connectivityVersion() != version && flipsMadeFacesCross(beforeFlips, state)) {
    FlowOptions noFlips = state.options();
    noFlips.flipEdges = false;
    state = FlowState(beforeFlips, state.selection(), noFlips, state.internalOptions(), state.slider());
    state.maintain(area0);
  }
}

// The tail of a stage: kTailWindow accepted steps that lowered E by at most kTailPlateau of it.
// At steps of at least T each (every mode relaxed within each), the shape has settled and what
// still moves is the mesh over it (the elk: 150 steps far beyond T moving vertices 0.05 ℓ
// along their normals while E fell by 0.1 %); below T, the mesh holds the steps back (joint:
// 200 steps at 1e-3 T, each refused above it), and the schedule remeshes. The resolution
// check (flow/resolution_check.h) judges what this rule calls converged.
class StageTail {
 public:
  explicit StageTail(double energy) : steps_{{energy, 0.0}} {}
  // Adds an accepted step; with the rule applied (`judge`), whether the tail ends the stage: true
  // with report.stop and `end` set.
  bool ends(double energy, double accepted, double shapeTime, bool judge, FlowReport& report, StageEnd& end) {
    constexpr int kTailWindow = 10;
    constexpr double kTailPlateau = 1e-3;
    steps_.emplace_back(energy, accepted);
    if (!judge || static_cast<int>(steps_.size()) <= kTailWindow) return false;
    const double before = steps_.front().first;
    steps_.pop_front();
    if (before - energy > kTailPlateau * std::max(std::abs(energy), 1.0)) return false;
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto& t : steps_) smallest = std::min(smallest, t.second);
    const bool converged = smallest >= shapeTime;
    report.stop = converged ? StopReason::Converged : StopReason::Stalled;
    end = converged ? StageEnd::Settled : StageEnd::MeshBound;
    return true;
  }

 private:
  std::deque<std::pair<double, double>> steps_;  // (E, accepted step) per accepted step
};

// The vector scheme (flow/vector_integrator.h) with adaptive τ (×2 after a step, ×0.5 after a
// refusal, below the last refused size). "Converged" is a statement about the shape at the flow's
// own time scale, the relaxation time T = A²/kShapeScaleFactor of the moving region's slowest
// bending mode (A its area): two accepted steps in a row whose normal motion, carried on for T
// (at τ ≥ T the step itself), moves no vertex by more than `shapeTolerance` mean edge lengths, or
// the stage's tail (StageTail). An energy rate alone is not used: near a round sphere E is so flat
// that a 2 % ellipsoid reads as converged by any energy rate that a torus's slow mesh drift does
// not also trip; the tail rule asks for steps of at least T, which relax such a mode within each
// step, and the schedule checks a converged state's resolution. The state with
// the lowest energy E is kept (`best`). Ends SelfContact when refusals by the embedding guard
// drove τ to kStuckFactor of the stage's largest accepted step (or of T, if that is smaller).
// Ends NeckFormed when κℓ rises above 0.6 and above 1.25× its reference (the energy would let a
// neck pinch for free: a torus's hole closing at E 60 where no torus goes below 8π² ≈ 79), and
// MeshBound when τ fell to kStuckFactor of that step for other refusals (a mesh distorted by a
// large change of shape); report.stop says Stalled, and the schedule remeshes and flows again.
// The neck's reference is κℓ at the stage's start, except in the first stage of a run on a region
// with handles (NeckRule::lowestSoFar), where it is the lowest κℓ so far: an input's creases and
// limbs a few edges across say nothing about a neck. After a remeshing the start is the reference
// (the remesher has just set ℓ ≈ 0.4/κ). The stuck rule is measured against T too: after a step far
// beyond T, a remeshed stage's first refusals are not stuck. Measurements: docs/decisions.md,
// "The schedule's rules".
StageEnd vectorStage(FlowState& state, Run& run, FlowStage& stage, double shapeTolerance, bool guardEmbedding,
                     bool startAtShapeScale, bool firstStage, bool withHandles, bool remeshing, double& lastTau, TriMesh& best,
                     double& bestEnergy) {
  VectorIntegrator integrator;
  const CountCrossings<VectorIntegrator> countCrossings{integrator, run.report};
  FlowReport& report = run.report;
  const double ell = state.geometry().meanEdgeLength;
  const double ell4 = ell * ell * ell * ell;
  const double area0 = state.activeArea();
  const double shapeTime = area0 * area0 / kShapeScaleFactor;
  configureVectorIntegrator(integrator, state, guardEmbedding, withHandles, shapeTime);
  VectorStepSize step{std::max(kInitialTau * ell4, lastTau * kStageTauCarry)};
  // The shape came converged from the coarser level: only what the subdivision changed is new, and
  // it relaxes at any step.
  if (startAtShapeScale) step.tau = std::max(step.tau, shapeTime);
  int settled = 0;
  int crossingsInARow = 0, contactSteps = 0;
  constexpr int kContactSteps = 10;
  TriMesh beforeFlips;
  NeckRule neck{firstStage && withHandles, largestCurvatureTimesEdge(state)};
  StageTail tail(state.energy());
  bestEnergy = state.energy();
  best = state.mesh();
  while (!run.limitReached()) {
    ++report.steps;
    if (!integrator.tryStep(state, step.tau)) {
      ++report.rejectedSteps;
      crossingsInARow = integrator.lastRejectionCrossed() ? crossingsInARow + 1 : 0;
      step.refused(withHandles, shapeTime);
      if (step.stuck(ell4, shapeTime)) {
        report.stop = crossingsInARow > 0 ? StopReason::SelfContact : StopReason::Stalled;
        return crossingsInARow > 0 ? StageEnd::Settled : StageEnd::MeshBound;
      }
      continue;
    }
    // A surface pressed against itself step after step (a knotted tube swelling into itself) has
    // no embedded way to go on lowering E: kContactSteps accepted steps in a row that held
    // vertices back from crossing end the stage. A contact that passes (a limb brushing the body
    // on its way in) does not.
    contactSteps = integrator.lastStepHeldContact() ? contactSteps + 1 : 0;
    if (contactSteps >= kContactSteps) {
      report.stop = StopReason::SelfContact;
      return StageEnd::Settled;
    }
    maintainGuarded(state, area0, guardEmbedding, beforeFlips);
    ++stage.steps;
    run.time += step.tau * integrator.lastExtrapolation();
    const double accepted = step.tau * integrator.lastExtrapolation();
    lastTau = step.tau;
    step.acceptedStep(accepted, integrator.lastStepShortened());
    const double energy = state.energy();
    if (run.record(state, stage.level, energy)) return StageEnd::Settled;
    if (neck.formed(largestCurvatureTimesEdge(state))) {
      // The energy from here on is the mesh's, not the surface's: this state is not kept.
      report.stop = StopReason::Stalled;
      return StageEnd::NeckFormed;
    }
    if (energy < bestEnergy) {
      bestEnergy = energy;
      best = state.mesh();
    }
    // The tail rule only where the schedule remeshes (`remeshing`: with the connectivity kept, the
    // mesh is the user's), and on shapes with handles (on genus 0 its stops moved a noisy sphere's
    // remeshings apart between MeshLab's float input and the CLI's double,
    // tests/plugin/meshlabserver_test.cpp).
    StageEnd end = StageEnd::Settled;
    if (tail.ends(energy, accepted, shapeTime, remeshing && withHandles, report, end)) return end;
    // The normal motion this step shows, carried on over the slowest mode's time T: at τ ≥ T the
    // step itself (it relaxes every mode at once), below it the normal speed times T.
    const double ellNow = state.geometry().meanEdgeLength;
    const double predicted = integrator.lastNormalMove() * std::max(1.0, shapeTime / accepted);
    settled = !integrator.lastStepShortened() && predicted <= shapeTolerance * ellNow ? settled + 1 : 0;
    if (settled >= 2) {
      report.stop = StopReason::Converged;
      return StageEnd::Settled;
    }
  }
  return StageEnd::Settled;
}

// FlowOptions::featureSize under the vector scheme: the flow's principal part for the amount's
// flow time, kFeatureSteps steps of one factorisation (flow/principal_part_filter.h). No step is
// refused: the filter is linear and each step lowers the principal part's energy ¼ XᵀC M⁻¹C X.
// With uniform operators (AmountOperators::Graph: a rough scan) the amount is twiced (Tukey): the
// same steps run again on what the first pass took away, which is added back filtered,
// x = g(x₀) + g(x₀ − g(x₀)). Its response 1 − (1 − g)² keeps the shapes larger than the amount
// to second order where g alone bends them to first, and still takes 98 % off ripples of the
// amount's size. Measured on scans with vertex noise: docs/options.md, "The default amount".
void featureSizeStage(FlowState& state, Run& run, FlowStage& stage) {
  const double tau = run.timeLimit / kFeatureSteps;
  PrincipalPartFilter filter;
  if (!filter.prepare(state, tau, run.opt.amountOperators))
    throw NumericalError("fair: the fairing amount's matrix is not positive definite (a degenerate moving region)");
  const bool twiced = run.opt.amountOperators == AmountOperators::Graph;
  std::vector<Vec3> start;  // x₀, for the second pass
  if (twiced) start = state.positions();
  auto failed = [] { throw NumericalError("fair: the fairing amount's step is not finite"); };
  while (!run.limitReached()) {
    ++run.report.steps;
    if (!filter.step(state)) failed();
    ++stage.steps;
    run.time += tau;
    if (run.record(state, stage.level, state.energy())) return;
  }
  if (!twiced || run.report.stop != StopReason::FeatureSize) return;
  // The second pass is part of the same flow time's filter: its solves count as no further steps
  // (FlowOptions::maxSteps counts the amount's four).
  if (!filter.addBackFilteredRemoval(state, std::move(start), static_cast<int>(kFeatureSteps))) failed();
  // The history's last sample (the fourth step's) becomes the twiced result's: same step, same time.
  EnergySample& last = run.report.history.back();
  last.energy = state.energy();
  last.seconds = run.elapsed();
}

// The message names the selection only when there is one: without, the boundary holds them all.
void requireMovingVertex(const FlowState& state, bool selection) {
  if (state.roles().freeCount != 0 || state.roles().slidingCount != 0) return;
  if (selection)
    throw InvalidInputError(
        "fair: no vertex can move (a moving vertex needs all its faces selected and, with a fixed "
        "boundary, must be at least two rings away from the boundary)");
  throw InvalidInputError(
      "fair: no vertex can move: every vertex is on the boundary or next to it, and a fixed boundary keeps "
      "those two rings in place (the mesh is too small for its boundary; a sliding boundary lets it move)");
}

// The energy where the run's first flow starts (after any refinement before it), as the report's
// initial energy and the first entry of its history.
void recordStart(FlowReport& report, FlowState& state) {
  report.energyInitial = state.energy();
  report.history.push_back({0, 0, 0, report.energyInitial});
}

// A stage's record as it starts: its level and the size of the mesh it flows.
FlowStage beginStage(const FlowState& state, int level) {
  FlowStage stage;
  stage.level = level;
  stage.vertices = state.mesh().vertexCount();
  stage.faces = state.mesh().faceCount();
  return stage;
}

// Ends a stage that began at `stageStart` (run time): `region` takes its state (the state is not to
// be used after), the report its record.
void endStage(FlowState& state, FlowStage& stage, double stageStart, Run& run, MovingRegion& region) {
  stage.energy = state.energy();
  region = state.releaseRegion();
  if (run.stageEnded) run.stageEnded(region.mesh(), region.selection());
  stage.seconds = run.elapsed() - stageStart;
  run.report.stages.push_back(stage);
  run.report.energyFinal = stage.energy;
}

// The run's lowest-energy stage end at one level of the schedule (its resolution), kept as the
// output if the run ends above it (issue 40: the elephant's fourth stage reached E 137.5 and its
// last ended at 141.3). Only states whose mesh resolves them count (flow/resolution_check.h).
struct KeptState {
  TriMesh mesh;
  std::vector<std::uint8_t> selection;
  double energy = std::numeric_limits<double>::infinity();
  int level = -1;
};
void keepIfBest(KeptState& kept, const MovingRegion& region, double energy, int level) {
  if (!(energy < kept.energy) && kept.level == level) return;
  kept = {region.mesh(), region.selection(), energy, level};
}
// Halvings of the remeshing's edges around faces it made cross (remeshMovingRegion), on meshes with
// handles: femur's tunnels are 0.4 of its median edge wide.
constexpr int kCrossingRefinements = 4;
// Refinements where the schedule would have stopped converged on an unresolved state.
constexpr int kMaxUnresolvedRefinements = 3;

// A moving region whose vertices were jittered in 3-D (a scan's noise, a mesh perturbed by
// hand) has folded faces and needle corners, which the vector scheme's cotangent operators read as
// curvature, and its few folded vertices make every step short. A region that no remeshing
// resamples (FlowOptions::remesh off) is untangled (mesh/tangential_relaxation.h: tangential moves
// only) before its first stage when a corner is under kTangledAngle or a face is folded against
// its corners' normals (`always` false), and whatever its angles (`always`) when the schedule asks
// for it (NextStage::Untangle), as a remeshing pipeline would remesh. Reported as
// FlowReport::untanglePasses; measurements: docs/decisions.md, "The schedule's rules".
constexpr double kTangledAngleDegrees = 1;
// An untangling that makes faces cross where none crossed is undone: relaxed tangentially over
// their slivers, the vertices of thin-walled CAD parts slid through the walls, and the embedding
// guard then refused every step after (docs/decisions.md, "CAD parts").
void untangleMovingRegion(MovingRegion& region, bool always, FlowReport& report) {
  const VertexRoles& roles = region.roles();
  if (roles.freeCount == 0 || !(always || isTangled(region.mesh(), roles.activeFace, kTangledAngleDegrees))) return;
  const bool crossedBefore = selfIntersects(region.mesh(), &roles.activeFace);
  std::vector<Vec3> before = region.mesh().positions;
  int passes = 0;
  region.movePositions([&](TriMesh& mesh) { passes = untangle(mesh, roles.free, roles.activeFace); });
  if (!crossedBefore && selfIntersects(region.mesh(), &roles.activeFace)) {
    region.movePositions([&](TriMesh& mesh) { mesh.positions = std::move(before); });
    return;
  }
  report.untanglePasses += passes;
}

// Whether a stalled run's output is a worse surface than its input: its energy Loop-subdivided once
// (resolution_check.h: what a mesh cannot hide by crumpling or pinching below its edges, and what
// a CAD tessellation's slivers cannot hide either) above the input's. A thin CAD tube remeshed on
// its surface (remeshTessellation) can have its wall's sheets pressed together by the flow and
// stall crumpled, worse than it came (docs/decisions.md, "CAD parts").
bool outputIsWorse(const TriMesh& output, const TriMesh& input, const FlowOptions& opt) {
  Resolution in, out;
  return measureResolution(input, opt, in) && measureResolution(output, opt, out) && out.loopEnergy > in.loopEnergy;
}

// A whole mesh's output that crosses itself where its input did not is refused, and a run whose
// output is its input says so: the input comes back with StopReason::Unchanged and the reason in
// FlowReport::refusedBecause. No step's guard lets faces cross, but a state the schedule adopts
// without a step can: on rotor and anchor an untangling and then remeshings made 511 and 245 faces
// cross, every step after was refused, and the run said `stalled` on them.
// A stalled run's output that is a worse surface than its input is refused too (outputIsWorse).
void refuseBrokenOutput(MovingRegion& region, TriMesh&& input, const FlowOptions& opt, FlowReport& report) {
  if (report.stop == StopReason::Cancelled) return;
  const bool crosses = !report.inputSelfIntersects && selfIntersects(region.mesh());
  const bool same = region.mesh().faces == input.faces && region.mesh().positions == input.positions;
  const bool worse = !crosses && !same && report.stop == StopReason::Stalled && outputIsWorse(region.mesh(), input, opt);
  // A run the time limit ended before it kept anything (its remeshings cut by the limit) says so:
  // the input is the best state it reached.
  if (!crosses && !worse && (!same || report.stop == StopReason::MaxSeconds)) return;
  if (crosses || worse) {
    report.refusedBecause = crosses ? "faces of the output cross each other (the input's did not)"
                                    : "the output, Loop-subdivided, has a higher energy than the input";
    region.edit([&](TriMesh& mesh, std::vector<std::uint8_t>&) {
      mesh = std::move(input);
      return true;
    });
  } else {
    report.refusedBecause = std::string(report.remeshings == 0 ? "no remeshing of it was accepted, and " : "") +
                            "no state of the flow was kept below the input's energy";
  }
  report.keptStage = -1;
  report.stop = StopReason::Unchanged;
  report.energyFinal = regionEnergy(region.mesh(), {}, opt);
}

// The working resolution of a CAD tessellation whose isotropic remeshing was refused: its long
// edges split first (splitLongEdges: no input vertex moves), then remeshed to edges sized by the
// part's thinnest feature (cadWorkingEdgeLength, measured on the input), or, if that remeshing is
// refused or the part has no measurable thickness, at the split mesh's own size. If all of these
// make faces cross (thin walls: rotor, anchor), the input is remeshed on its own surface at the
// working edge (remeshOnSurface: no vertex leaves the input's faces, its sharp edges stay), and
// `onSurface` says so. The region is as it came if every remeshing is refused.
bool remeshTessellation(MovingRegion& region, bool& onSurface) {
  TriMesh mesh = region.mesh();
  std::vector<std::uint8_t> selection = region.selection();
  const double working = cadWorkingEdgeLength(region);
  if (!splitLongEdges(region)) return onSurface = working > 0 && remeshOnSurface(region, working);
  const double target = isotropicTargetEdge(region);
  if (working > 0 && target > 0 && remeshMovingRegion(region, false, working / target)) return true;
  if (remeshMovingRegion(region, false)) return true;
  region.edit([&](TriMesh& out, std::vector<std::uint8_t>& sel) {
    out = std::move(mesh);
    sel = std::move(selection);
    return true;
  });
  return onSurface = working > 0 && remeshOnSurface(region, working);
}

// Whether `region` at `atLevel` is the region (mesh and selection, bit for bit) kept at `level`.
bool isRegionAt(const TriMesh& mesh, const std::vector<std::uint8_t>& selection, int level, const MovingRegion& region,
                int atLevel) {
  return level == atLevel && selection == region.selection() && mesh.faces == region.mesh().faces &&
         mesh.positions == region.mesh().positions;
}

// The start of the last stage that flowed (the region and the level) and how it ended: the
// schedule's verdict, its stop reason and whether it was to refine later.
struct LastStage {
  TriMesh mesh;
  std::vector<std::uint8_t> selection;
  int level = -1;
  StageVerdict verdict;
  bool refineLater = false;
  StopReason stop = StopReason::Converged;
};
// Whether a reflow whose remeshing was refused would flow the last stage again: the region is
// where that stage started, at the same level (the stage ended where it started, and the remeshing
// left it so). The vector scheme's stage is a function of its start but for its first step τ,
// carried from the last stage's last; from a stage that ended at its start that step is far beyond
// the region's shape time T, where the step no longer depends on τ. It is not run again: the
// schedule judges the last stage's verdict once more (a repeated stage gave every energy the same
// to the last digit: docs/decisions.md, "Regions").
bool repeatsLastStage(const LastStage& last, const MovingRegion& region, int level) {
  return isRegionAt(last.mesh, last.selection, last.level, region, level);
}

// The region on which a reflow's curvature-adaptive remeshing was refused, at its level. That
// remeshing is a function of the region (its mesh and selection) and of the level's budget, so the
// same region at the same level is refused again without trying (a stage that ends where it started
// leaves the next reflow the same state; docs/decisions.md, "Regions").
struct RefusedRemeshing {
  TriMesh mesh;
  std::vector<std::uint8_t> selection;
  int level = -1;
  bool holds(const MovingRegion& region, int atLevel) const { return isRegionAt(mesh, selection, level, region, atLevel); }
};

// A fairing run's state from its preparation to its output's check: the options as the run changes
// them (the scheme after a fallback, the levels a coarse start adds) and what one stage leaves to
// the next.
struct RegionRun {
  RegionRun(MovingRegion& region, FlowOptions& opt, const FlowOptions& requested, const InternalFlowOptions& internal,
            Run& run, FlowReport& report, BoundarySlider* slider, int genus)
      : region(region), opt(opt), requested(requested), internal(internal), run(run), report(report), slider(slider),
        genus(genus) {}
  MovingRegion& region;
  FlowOptions& opt;
  const FlowOptions& requested;
  const InternalFlowOptions& internal;
  Run& run;
  FlowReport& report;
  BoundarySlider* slider;
  // The handles decide vectorStage's neck rule in the first stage, the budget and the resolution check.
  int genus;
  bool quality = false;  // the mesh kept fit for the operators (FlowOptions::remesh)
  FlowOptions stageOpt;  // the stages' options: the run's as prepared, with edge flips where quality
  int level = 0;
  // A whole mesh's input, for the check of its output (refuseBrokenOutput).
  bool wholeMesh = false;
  TriMesh input;
  // After each stage the schedule (flow/schedule.h) decides what follows: the same level again
  // (remeshed, or untangled with the connectivity kept), the next level, the semi-implicit scheme
  // from the start, or the end of the run.
  Schedule schedule;
  bool first = true, remeshAdaptively = false;
  double lastTau = 0;  // the semi-implicit scheme's last accepted step, carried into the next stage
  TriMesh best;  // the vector scheme's lowest-energy state of the current stage
  double bestEnergy = 0;
  CoarseStart coarse;
  int coarseLevels = 0;
  int refinements = 0;  // subdivisions made after the first stage
  bool onSurface = false;
  // The run's lowest-energy stage end at the current level whose mesh resolves it (keepIfBest), and
  // the refinements where a converged state was not resolved (resolutionRefines).
  KeptState kept;
  int unresolvedRefinements = 0;
  bool measureEach = false, checkResolution = false, keepEachStage = false;
  // The moving vertices this level may have (vertexBudget), ×4 per level; the report has the finest's.
  long long movingBudget = 0;
  LastStage last;
  RefusedRemeshing refused;
};

// The vector scheme descends the elastica energy; the comparison flows run the scheme they have.
// Scheme::Automatic: the vector scheme, handles or not (the semi-implicit one only where the vector
// scheme cannot take its first step: fallsBackToSemiImplicit). With the handles' rules the vector
// scheme converges small meshes with handles in fewer attempts than the semi-implicit one
// (docs/decisions.md, "The schedule's rules": the automatic scheme).
Scheme runScheme(const FlowOptions& requested) {
  Scheme scheme = requested.scheme;
  if (scheme == Scheme::Automatic) scheme = Scheme::Vector;
  if (scheme == Scheme::Vector && requested.flow == FlowType::LaplacianOfMeanCurvature) scheme = Scheme::SemiImplicit;
  if (requested.flow == FlowType::Bilaplacian) scheme = Scheme::Explicit;  // its only scheme (Automatic included)
  return scheme;
}

void requireSelectionSize(const MovingRegion& region) {
  const std::size_t selected = region.selection().size();
  if (selected != 0 && selected != region.mesh().faces.size())
    throw InvalidInputError("fair: the selection has " + std::to_string(selected) + " entries for " +
                            std::to_string(region.mesh().faces.size()) + " faces");
}

// A fairing amount keeps the user's vertices and connectivity: no refinement, no remeshing. Its
// one stage leaves the selection as it came, and every step in the history.
// The state takes the region, not a copy (34 MB of the peak at 711,420 vertices), and gives it back
// however the run ends, as the run left it (fairMasked's promise).
void fairAmount(RegionRun& f) {
  FlowState state(std::move(f.region), f.opt, f.internal, f.slider);
  try {
    requireMovingVertex(state, !state.selection().empty());
    recordStart(f.report, state);
    FlowStage stage = beginStage(state, 0);
    featureSizeStage(state, f.run, stage);
    endStage(state, stage, 0, f.run, f.region);  // the run's only stage: it started with the run
  } catch (...) {
    f.region = state.releaseRegion();
    throw;
  }
  f.report.seconds = f.run.elapsed();
}

// The semi-implicit pipeline keeps the mesh fit for the operators (FlowOptions::remesh,
// flow/mesh_quality_stage.h): first the working-resolution floor, within the levels asked for.
void prepare(RegionRun& f) {
  MovingRegion& region = f.region;
  f.quality = f.opt.scheme != Scheme::Explicit && f.opt.remesh;
  f.stageOpt = f.opt;
  if (f.quality) f.stageOpt.flipEdges = true;
  f.wholeMesh = f.quality && region.selection().empty();
  if (f.wholeMesh) f.input = region.mesh();
  if (f.quality) {
    f.level = f.report.preSubdivisions = subdivideToWorkingResolution(region, f.opt);
    // A selection's guard asks about the faces that move: crossings elsewhere in a scan leave it on.
    f.report.inputSelfIntersects = region.selection().empty()
                                       ? selfIntersects(region.mesh())
                                       : selfIntersects(region.mesh(), &region.roles().activeFace);
  }
}

// A fairing amount (FlowOptions::featureSize) keeps the user's vertices: an isotropic remeshing
// first would resample the surface and smooth it below its edge length, whatever the amount.
// A large mesh starts coarse (coarseStart: a closed one, or one with a border whose moving part is
// large): its levels are added to the schedule's. A coarse remeshing that would make faces cross
// is undone; the mesh is remeshed at its own size.
void chooseStartingResolution(RegionRun& f) {
  MovingRegion& region = f.region;
  FlowReport& report = f.report;
  const bool quality = f.quality, timeLimited = f.run.timeLimited();
  f.coarse = quality && f.opt.scheme == Scheme::Vector && !timeLimited ? coarseStart(region) : CoarseStart{};
  f.coarseLevels = f.coarse.levels;
  if (f.coarseLevels > 0 && !remeshMovingRegion(region, false, f.coarse.coarsening)) f.coarseLevels = 0;
  // A part remeshed on its surface (remeshTessellation: thin walls that every other remeshing put
  // through each other) is remeshed on its surface later too: curvature-adaptive remeshings free to
  // relax off it pressed rotor's wall's sheets together, and it stalled; kept on it, it became the
  // Clifford torus (docs/decisions.md, "CAD parts").
  if (f.coarseLevels > 0) {
    ++report.remeshings;
    f.opt.subdivisionLevels += f.coarseLevels;
    report.coarseStartLevels = f.coarseLevels;
  } else if (quality && !timeLimited && !(f.genus > 0 && isotropicEdgeMissesThinnest(region)) &&
             remeshMovingRegion(region, false)) {
    // A part with handles whose thin walls the isotropic edge would step over is sized by its
    // thinnest feature instead (remeshTessellation, next).
    ++report.remeshings;
  } else if (quality && !timeLimited && region.selection().empty() && remeshTessellation(region, f.onSurface)) {
    // A CAD part's flow starts from a fresh triangulation (remeshTessellation). A selection's does
    // not: its remeshing is judged against the scan around it, and on man.off Loop ×2's
    // 50,000-face region (its isotropic remeshing undone: faces crossed the foot beside it) the
    // split mesh's remeshing stacked vertices and was undone too, after 3–4 s of work before the
    // first step (docs/decisions.md, "Regions").
    ++report.remeshings;
  } else if (quality && !timeLimited && f.genus > 0 &&
             remeshMovingRegion(region, false, 1, 0, nullptr, kCrossingRefinements)) {
    // Sheets closer than the edge length (femur: 0.4 median edges) made both remeshings cross:
    // refined where they crossed instead (without, the raw scan was untangled into crossing faces
    // and every vector step was refused for them).
    ++report.remeshings;
  } else if (f.opt.scheme == Scheme::Vector) {
    untangleMovingRegion(region, false, report);
  }
}

// Which stage ends the run keeps and measures, and the moving vertices each level may have.
void setStageRules(RegionRun& f) {
  const bool quality = f.quality;
  // The resolution check is the vector scheme's (the default; the semi-implicit scheme's stops are
  // the user's tolerances, which may ask for an early stop), on whole closed meshes with handles.
  // Genus 0 is left as it was: its scans end within 0.2–1.4 % of their Loop-1 energy, and a
  // 162-vertex noisy sphere (tests/plugin/meshlabserver_test.cpp), resolved within 3.3 % at its
  // first stage, was refined there, after which MeshLab's float run and the CLI's double one
  // remeshed it to different vertex counts.
  f.measureEach = quality && f.region.selection().empty();
  f.checkResolution = f.measureEach && f.genus > 0;
  // A selection keeps its lowest stage end at the level (keepIfBest), without the resolution
  // check, which is the whole mesh's: on lion-head's recipe region 0 the last of three stages, after
  // a reflow's curvature-adaptive remeshing, ended at E 32.65 where the second had ended at 22.2, and
  // the run said converged on the last (docs/decisions.md, "Regions").
  f.keepEachStage = quality && !f.region.selection().empty();
  if (quality) {
    f.movingBudget = vertexBudget(f.region.roles().freeCount, f.genus);
    const long long fixed = f.region.mesh().vertexCount() - f.region.roles().freeCount;
    f.report.vertexBudget =
        fixed + f.movingBudget * (1LL << (2 * std::max(0, f.opt.subdivisionLevels - f.level)));
  }
}

// A stage's verdict and what the schedule weighs beside it.
struct StageOutcome {
  StageVerdict verdict;
  bool firstStage = false, refineLater = false;
  double previousEnergy = 0;
  bool measured = false;
  Resolution resolution;
};

// The reflow's curvature-adaptive remeshing before a stage; true if it was refused.
bool remeshingRefused(RegionRun& f) {
  if (!f.remeshAdaptively) return false;
  f.remeshAdaptively = false;
  MovingRegion& region = f.region;
  if (f.refused.holds(region, f.level)) return true;
  if (remeshMovingRegion(region, true, 1, f.movingBudget, nullptr, f.genus > 0 ? kCrossingRefinements : 0,
                         f.onSurface)) {
    ++f.report.remeshings;
    return false;
  }
  ++f.report.remeshingsRefused;
  f.refused = RefusedRemeshing{region.mesh(), region.selection(), f.level};
  return true;
}

// The stage's flow in the run's scheme, from `state` at `stageStart`.
StageEnd flowInScheme(RegionRun& f, FlowState& state, FlowStage& stage, const StageOutcome& outcome, double stageStart) {
  const FlowOptions& opt = f.opt;
  const bool refineLater = outcome.refineLater;
  if (opt.scheme == Scheme::Explicit)
    return explicitStage(state, f.run, stage, refineLater ? opt.subdivisionTolerance : opt.energyTolerance, stageStart);
  if (opt.scheme == Scheme::Vector) {
    const StageEnd end = vectorStage(
        state, f.run, stage, kVectorShapeTolerance * (refineLater ? 10 : 1), f.quality && !f.report.inputSelfIntersects,
        f.coarseLevels > 0 && f.level > 0 && f.schedule.reflows() == 0, outcome.firstStage, f.genus > 0, f.quality,
        f.lastTau, f.best, f.bestEnergy);
    // The stage's output is its lowest-energy state (before any neck formed).
    if (end == StageEnd::NeckFormed || f.bestEnergy < state.energy())
      state = FlowState(f.best, state.selection(), f.stageOpt, f.internal, f.slider);
    return end;
  }
  const double plateau = opt.plateauTolerance * (refineLater ? kSubdivisionPlateauFactor : 1.0);
  return semiImplicitStage(state, f.run, stage, refineLater ? opt.subdivisionTolerance : opt.energyTolerance, plateau,
                           f.quality && !f.report.inputSelfIntersects, f.lastTau);
}

// One stage at the current level, or the last one's verdict where it would repeat it (repeatsLastStage).
StageOutcome flowStage(RegionRun& f) {
  MovingRegion& region = f.region;
  FlowReport& report = f.report;
  StageOutcome outcome;
  if (remeshingRefused(f) && f.opt.scheme == Scheme::Vector && repeatsLastStage(f.last, region, f.level)) {
    outcome.verdict = f.last.verdict;
    outcome.refineLater = f.last.refineLater;
    report.stop = f.last.stop;
    outcome.previousEnergy = f.last.verdict.energy;
    return outcome;
  }
  f.last = LastStage{};
  f.last.mesh = region.mesh();
  f.last.selection = region.selection();
  f.last.level = f.level;
  FlowState state(region.copyTakingCaches(), f.stageOpt, f.internal, f.slider);
  requireMovingVertex(state, !region.selection().empty());
  outcome.refineLater = f.level < f.opt.subdivisionLevels &&
                        (f.opt.targetEdgeLength <= 0 || state.geometry().meanEdgeLength > f.opt.targetEdgeLength);
  const double stageStart = f.run.elapsed();
  if (f.first) {
    recordStart(report, state);
    f.first = false;
  }
  FlowStage stage = beginStage(state, f.level);
  outcome.firstStage = report.stages.empty();
  StageEnd end = StageEnd::Settled;
  try {
    end = flowInScheme(f, state, stage, outcome, stageStart);
  } catch (const FlowDivergedError&) {
    region = state.releaseRegion();  // the restored checkpoint (faces may have been flipped)
    throw;
  }
  endStage(state, stage, stageStart, f.run, region);
  outcome.verdict = {end, stage.steps, stage.energy};
  f.last.verdict = outcome.verdict;
  f.last.refineLater = outcome.refineLater;
  f.last.stop = report.stop;
  if (report.stages.size() >= 2) outcome.previousEnergy = report.stages.end()[-2].energy;
  return outcome;
}

// The stage end's resolution, and the stage end kept where it is the level's best.
void measureStage(RegionRun& f, StageOutcome& outcome) {
  outcome.measured = f.measureEach && measureResolution(f.region.mesh(), f.opt, outcome.resolution);
  if ((outcome.measured && outcome.resolution.resolved()) || f.keepEachStage)
    keepIfBest(f.kept, f.region, outcome.verdict.energy, f.level);
}

// What the schedule (flow/schedule.h) weighs beside the stage's verdict.
ScheduleContext scheduleContext(RegionRun& f, const StageOutcome& outcome) {
  ScheduleContext context;
  context.scheme = f.opt.scheme;
  context.automatic = f.requested.scheme == Scheme::Automatic;
  context.quality = f.quality;
  context.firstStage = outcome.firstStage;
  context.refineLater = outcome.refineLater;
  context.previousEnergy = outcome.previousEnergy;
  context.stopped = [&f] { return f.run.stopped || f.run.limitReached(); };
  context.needsRemeshing = [&f] { return needsRemeshing(f.region); };
  return context;
}

// A run never says converged on a state its mesh does not resolve: refined where the gap is,
// it flows on (kMaxUnresolvedRefinements times at most); else it says stalled. True if refined.
// A surface pressed against itself (self_contact) is a result too, and the same promise: a
// knotted tube swollen against itself ended at Loop-1 +4.5 % (knot1).
bool refinedWhereUnresolved(RegionRun& f, const StageOutcome& outcome) {
  FlowReport& report = f.report;
  const bool final = report.stop == StopReason::Converged || report.stop == StopReason::SelfContact;
  if (!(f.checkResolution && f.opt.scheme == Scheme::Vector && outcome.measured && final &&
        !outcome.resolution.resolved()))
    return false;
  if (f.unresolvedRefinements < kMaxUnresolvedRefinements && !(f.run.stopped || f.run.limitReached()) &&
      remeshMovingRegion(f.region, true, 1, f.movingBudget, &outcome.resolution.unresolved, kCrossingRefinements,
                         f.onSurface)) {
    ++f.unresolvedRefinements;
    ++report.remeshings;
    return true;
  }
  report.stop = StopReason::Stalled;
  return false;
}

// The next level: a quarter of the faces' size, the budget ×4, the kept state the old level's.
void refine(RegionRun& f) {
  MovingRegion& region = f.region;
  f.movingBudget *= 4;
  f.kept = KeptState{};
  // A coarse start's shape comes smooth from its level, and Loop's masks keep it smooth: the
  // midpoints' facets would be creases for the finer level to flow out.
  // A mesh with a border refines only its moving faces: its fixed rows stay the user's.
  if (f.coarseLevels > 0 && f.coarse.onMovingFaces && f.refinements < f.coarseLevels)
    subdivideMovingFaces(region);
  else if (f.coarseLevels > 0 && !f.coarse.onMovingFaces)
    region.edit([](TriMesh& mesh, std::vector<std::uint8_t>&) {
      subdivideLoop(mesh);
      return true;
    });
  else
    subdivideOneLevel(region);
  ++f.refinements;
}

// The same level again: with the other scheme, remeshed, or untangled with the connectivity kept.
void repeatLevel(RegionRun& f, NextStage next) {
  if (next == NextStage::FallBack) {
    // The stage that took no step is not the run's: it starts over with the other scheme.
    f.report.stages.pop_back();
    f.opt.scheme = f.report.scheme = Scheme::SemiImplicit;
  } else if (next == NextStage::Reflow) {
    f.remeshAdaptively = true;
  } else {
    untangleMovingRegion(f.region, true, f.report);
  }
}

// The stages, level by level, until the schedule stops the run.
void runStages(RegionRun& f) {
  for (;; ++f.level) {
    StageOutcome outcome = flowStage(f);
    measureStage(f, outcome);
    const NextStage next = f.schedule.next(outcome.verdict, scheduleContext(f, outcome), f.report.stop);
    if (next == NextStage::Stop && refinedWhereUnresolved(f, outcome)) {
      --f.level;
      continue;
    }
    if (next == NextStage::Stop) return;
    if (next == NextStage::Refine) {
      refine(f);
      continue;
    }
    --f.level;
    repeatLevel(f, next);
  }
}

// The final approach with the connectivity kept: the vector scheme's converged state is the
// minimiser of W on this triangulation, whose tangential freedom can trade roundness for energy
// where the mesh is irregular; the paper's normal flow, after the vertices are evened out
// tangentially, settles where the shape is the surface's, not the triangulation's.
void flowFinalApproach(RegionRun& f) {
  if (!finalApproach(f.opt.scheme, f.quality, f.run.stopped, f.report.stop)) return;
  untangleMovingRegion(f.region, true, f.report);
  FlowState state(f.region.copyTakingCaches(), f.stageOpt, f.internal, f.slider);
  FlowStage stage = beginStage(state, f.level);
  const double stageStart = f.run.elapsed();
  semiImplicitStage(state, f.run, stage, f.opt.energyTolerance, f.opt.plateauTolerance, false, f.lastTau);
  endStage(state, stage, stageStart, f.run, f.region);
}

// The output is never above the run's best state at its final resolution (by more than
// kConfirmedPlateau, the schedule's measure of equal energies: two stage ends within it are the
// same plateau, and a choice between them would follow the rounding of the input, float or
// double, and not the shape). A whole mesh's output is then checked against its input.
void checkOutput(RegionRun& f) {
  FlowReport& report = f.report;
  if (f.kept.level == f.level && f.kept.energy < (1 - kConfirmedPlateau) * report.energyFinal) {
    f.region.edit([&](TriMesh& mesh, std::vector<std::uint8_t>& selection) {
      mesh = std::move(f.kept.mesh);
      selection = std::move(f.kept.selection);
      return true;
    });
    report.energyFinal = f.kept.energy;
  }
  if (f.wholeMesh) refuseBrokenOutput(f.region, std::move(f.input), f.opt, report);
  report.seconds = f.run.elapsed();
  if (report.history.back().step != report.steps)
    report.history.push_back({report.steps, f.run.time, report.seconds, report.energyFinal});
}

// fairMasked() on its region: the mesh and the selection as the run leaves them stay in `region`.
// A fairing amount flows once; any other run is prepared, starts at its resolution, flows in
// stages (the schedule deciding after each), approaches the end, and has its output checked.
FlowReport fairRegion(MovingRegion& region, const FlowOptions& requested, const InternalFlowOptions& internal,
                      const StageEnded& stageEnded) {
  FlowOptions opt = requested;
  const int genus = closedGenus(region.topology());
  opt.scheme = runScheme(requested);
  FlowReport report;
  report.scheme = opt.scheme;
  Run run{opt, internal, report, stageEnded};
  region.setDeadline(run.deadline());
  requireSelectionSize(region);
  std::unique_ptr<BoundarySlider> slider;
  if (opt.boundary == BoundaryMode::Slide) slider = std::make_unique<BoundarySlider>(region.topology(), region.mesh().positions);
  RegionRun f(region, opt, requested, internal, run, report, slider.get(), genus);
  if (opt.scheme == Scheme::Vector && run.timeLimited()) {
    fairAmount(f);
    return report;
  }
  prepare(f);
  chooseStartingResolution(f);
  setStageRules(f);
  runStages(f);
  flowFinalApproach(f);
  checkOutput(f);
  return report;
}

}  // namespace

FlowReport fairMasked(TriMesh& mesh, std::vector<std::uint8_t>* faceSelected, const FlowOptions& requested,
                      const InternalFlowOptions& internal, const StageEnded& stageEnded) {
  validate(requested, internal);
  // The run works on a region that owns the mesh and the selection; the mesh goes back to the
  // caller as the run leaves it, on success and on failure alike (as when the run worked on the
  // caller's mesh in place).
  MovingRegion region(std::move(mesh), faceSelected ? *faceSelected : std::vector<std::uint8_t>{}, requested.boundary);
  try {
    FlowReport report = fairRegion(region, requested, internal, stageEnded);
    if (faceSelected && !faceSelected->empty()) *faceSelected = region.selection();
    mesh = region.release();
    return report;
  } catch (...) {
    mesh = region.release();
    throw;
  }
}

FlowReport fair(TriMesh& mesh, const FlowOptions& opt) { return fairMasked(mesh, nullptr, opt, {}); }

void validateFlowOptions(const FlowOptions& opt) { validate(opt, {}); }

}  // namespace elastica
