#include <elastica/errors.h>
#include <elastica/fairing.h>
#include "flow/fair_masked.h"
#include "flow/explicit_integrator.h"
#include "flow/flow_state.h"
#include "flow/mesh_quality_stage.h"
#include "flow/semi_implicit_integrator.h"
#include "mesh/self_intersection.h"

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
// A step τ ≥ A²/kShapeScaleFactor relaxes the slowest bending mode of a region of area A within
// the step (τ/2 · λ ≥ 1): the first eigenvalue of Δ² on a clamped disk of area A is ≈ 1030/A²,
// so 50 leaves a 10× margin for other shapes. See FlowOptions::shapeTolerance.
constexpr double kShapeScaleFactor = 50;

void validate(const FlowOptions& o) {
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
  if (o.flipInterval < 1) bad("flipInterval must be >= 1");
  if (!(o.maxJump > 0)) bad("maxJump must be > 0");
  if (o.driftPasses < 0) bad("driftPasses must be >= 0");
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
  FlowReport& report;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double time = 0;  // flow time
  bool stopped = false;

  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
  // Step and time limits; true if the run must stop.
  bool limitReached() {
    if (report.steps >= opt.maxSteps) report.stop = StopReason::MaxSteps;
    else if (opt.maxSeconds > 0 && elapsed() >= opt.maxSeconds) report.stop = StopReason::MaxSeconds;
    else return false;
    return stopped = true;
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

// Relative energy change per unit of normalised time t/A² (A the moving region's area), the
// explicit scheme's plateau measure: independent of the model's scale and of the step size, so
// one FlowOptions::energyTolerance means the same in both schemes.
double energyRate(double energyBefore, double energyAfter, double flowTime, double area) {
  const double dtHat = flowTime / (area * area);
  return (energyBefore - energyAfter) / (std::max(std::abs(energyAfter), 1.0) * dtHat);
}

// The paper's explicit scheme until the energy-rate plateau (`tolerance`) or a limit.
void explicitStage(FlowState& state, Run& run, FlowStage& stage, double tolerance, double stageStart) {
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
      return;
    }
    if (energy > blowUp) diverged("energy rose from " + fmt(lastEnergy) + " to " + fmt(energy));
    if (!(jump < kSizeJump && jump > 1 / kSizeJump))
      diverged("the mean edge length changed by a factor " + fmt(jump) + " since the last check");
    if (!(drift < kBlowUpFactor && drift > 1 / kBlowUpFactor))
      diverged("the mean edge length changed by a factor " + fmt(drift) + " since the stage began");
    checkpointEdge = edge;
    checkpoint = state.mesh().positions;
    checkpointStep = report.steps;
    if (run.record(state, stage.level, energy)) return;
    if (std::abs(energyRate(lastEnergy, energy, run.time - lastTime, state.activeArea())) < tolerance) return;
    lastEnergy = energy;
    lastTime = run.time;
  }
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
// E any more, or a limit.
void semiImplicitStage(FlowState& state, Run& run, FlowStage& stage, double rateTolerance, double plateauTolerance,
                       bool guardEmbedding, double& lastTau) {
  SemiImplicitIntegrator integrator;
  integrator.guardEmbedding(guardEmbedding);
  struct CountCrossings {  // however the stage ends
    const SemiImplicitIntegrator& integrator;
    FlowReport& report;
    ~CountCrossings() { report.crossingRejections += integrator.crossingRejections(); }
  } countCrossings{integrator, run.report};
  FlowReport& report = run.report;
  const double ell = state.geometry().meanEdgeLength;
  const double ell4 = ell * ell * ell * ell;
  const double area0 = state.activeArea();
  // A later stage (after a subdivision or a remeshing) starts near its predecessor's last step:
  // its shape is nearly settled already, and growing τ again from 0.05 ℓ⁴ would cost ~15 steps.
  double tau = std::max(kInitialTau * ell4, lastTau * kStageTauCarry);
  if (run.opt.startAtShapeScale) tau = std::max(tau, area0 * area0 / (10 * kShapeScaleFactor));
  double ceiling = std::numeric_limits<double>::infinity();  // the last step size that failed, raised slowly
  // The window holds, per accepted step, the flow time and the energy the normal steps have taken
  // off so far (drift passes and edge flips excluded: they redistribute vertices, and a stop
  // rule that counted them would wait on mesh changes rather than on the shape).
  double lowered = 0;
  std::deque<std::pair<double, double>> window{{lowered, run.time}};  // (lowered so far, flow time)
  while (!run.limitReached()) {
    ++report.steps;  // attempts count against maxSteps
    if (!integrator.tryStep(state, tau)) {
      ++report.rejectedSteps;
      ceiling = tau;
      tau *= kShrink;
      if (tau < kSmallestTau * ell4) {  // nothing lowers E any more
        report.stop = StopReason::Stalled;
        return;
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
    // A shortened step (FlowOptions::shortenJumps) went as far as a step may: a larger τ would
    // only be shortened again.
    if (!integrator.lastStepShortened()) tau = std::min(tau * kGrow, kCeilingMargin * ceiling);
    ceiling *= kCeilingGrow;
    const double energy = state.energy();
    if (run.record(state, stage.level, energy)) return;
    if (shapeSettled(state, integrator, accepted, run.opt.shapeTolerance)) return;
    lowered += integrator.lastEnergyDecrease();
    window.emplace_back(lowered, run.time);
    if (static_cast<int>(window.size()) <= kPlateauWindow) continue;
    const double decrease = lowered - window.front().first, timeBefore = window.front().second;
    window.pop_front();
    if (decrease <= plateauTolerance * std::max(std::abs(energy), 1.0)) return;
    if (std::abs(energyRate(energy + decrease, energy, run.time - timeBefore, state.activeArea())) < rateTolerance) return;
  }
}

}  // namespace

FlowReport fairMasked(TriMesh& mesh, std::vector<std::uint8_t>* faceSelected, const FlowOptions& opt) {
  validate(opt);
  FlowReport report;
  Run run{opt, report};

  std::vector<std::uint8_t> selection = faceSelected ? *faceSelected : std::vector<std::uint8_t>{};
  if (!selection.empty() && selection.size() != mesh.faces.size())
    throw InvalidInputError("fair: the selection has " + std::to_string(selection.size()) + " entries for " +
                            std::to_string(mesh.faces.size()) + " faces");
  std::unique_ptr<BoundarySlider> slider;
  if (opt.boundary == BoundaryMode::Slide)
    slider = std::make_unique<BoundarySlider>(Topology(mesh.vertexCount(), mesh.faces), mesh.positions);

  // The semi-implicit pipeline keeps the mesh fit for the operators (FlowOptions::remesh,
  // flow/mesh_quality_stage.h): first the working-resolution floor, within the levels asked for.
  const bool quality = opt.scheme == Scheme::SemiImplicit && opt.remesh;
  FlowOptions stageOpt = opt;
  if (quality) stageOpt.flipEdges = true;
  int level = 0;
  if (quality) {
    level = report.preSubdivisions = subdivideToWorkingResolution(mesh, selection, opt);
    report.inputSelfIntersects = selfIntersects(mesh);
  }
  // A stage that leaves the mesh unfit for the operators (needsRemeshing) is remeshed and flowed
  // again, at most kMaxReflows times per level.
  constexpr int kMaxReflows = 2;
  bool first = true, adaptive = false;
  double lastTau = 0;  // the semi-implicit scheme's last accepted step, carried into the next stage
  int reflows = 0;
  if (quality && remeshMovingRegion(mesh, selection, opt.boundary, false)) ++report.remeshings;
  for (;; ++level) {
    if (adaptive && remeshMovingRegion(mesh, selection, opt.boundary, true)) ++report.remeshings;
    adaptive = false;
    FlowState state(mesh, selection, stageOpt, slider.get());
    if (state.roles().freeCount == 0 && state.roles().slidingCount == 0) {
      throw InvalidInputError(
          "fair: no vertex can move (a moving vertex needs all its faces selected and, with a fixed "
          "boundary, must be at least two rings away from the boundary)");
    }
    const bool refineLater = level < opt.subdivisionLevels &&
                             (opt.targetEdgeLength <= 0 || state.geometry().meanEdgeLength > opt.targetEdgeLength);
    const double stageStart = run.elapsed();
    if (first) {  // the energy where the first flow starts (after any refinement before it)
      report.energyInitial = state.energy();
      report.history.push_back({0, 0, 0, report.energyInitial});
      first = false;
    }
    FlowStage stage;
    stage.level = level;
    stage.vertices = state.mesh().vertexCount();
    stage.faces = state.mesh().faceCount();
    try {
      if (opt.scheme == Scheme::Explicit) {
        explicitStage(state, run, stage, refineLater ? opt.subdivisionTolerance : opt.energyTolerance, stageStart);
      } else {
        const double plateau = opt.plateauTolerance * (refineLater ? kSubdivisionPlateauFactor : 1.0);
        semiImplicitStage(state, run, stage, refineLater ? opt.subdivisionTolerance : opt.energyTolerance, plateau,
                          quality && !report.inputSelfIntersects, lastTau);
      }
    } catch (const FlowDivergedError&) {
      mesh = state.mesh();  // the restored checkpoint (faces may have been flipped)
      throw;
    }
    mesh = state.mesh();
    stage.energy = state.energy();
    stage.seconds = run.elapsed() - stageStart;
    report.stages.push_back(stage);
    report.energyFinal = stage.energy;
    // A limit reached just as the stage converged stops the run before it subdivides: a finer
    // mesh costs four times the memory and work, and its stage could not take a step.
    if (run.stopped || run.limitReached()) break;
    if (quality && reflows < kMaxReflows && needsRemeshing(mesh, selection, opt.boundary)) {
      ++reflows;  // remesh and flow this level again
      adaptive = true;
      --level;
      report.stop = StopReason::Converged;
      continue;
    }
    if (!refineLater) break;
    reflows = 0;
    report.stop = StopReason::Converged;  // the next stage decides
    subdivideOneLevel(mesh, selection);
  }
  if (faceSelected && !faceSelected->empty()) *faceSelected = selection;
  report.seconds = run.elapsed();
  if (report.history.back().step != report.steps)
    report.history.push_back({report.steps, run.time, report.seconds, report.energyFinal});
  return report;
}

FlowReport fair(TriMesh& mesh, const FlowOptions& opt) { return fairMasked(mesh, nullptr, opt); }

FlowReport fair(TriMesh& mesh, const FaceSet& region, const FlowOptions& opt) {
  std::vector<std::uint8_t> selection;
  try {
    selection = region.flags(mesh.faces.size());
  } catch (const InvalidInputError& e) {
    throw InvalidInputError(std::string("fair: the region's ") + e.what());
  }
  FlowReport report = fairMasked(mesh, &selection, opt);
  report.regionFaces = FaceSet::fromFlags(selection).faces;
  return report;
}

}  // namespace elastica
