#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/flow_state.h>
#include <elastica/subdivision.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>

namespace elastica {
namespace {

// An energy this many times its value at the start of a stage (and at least this many times 1),
// a mean edge length changing by kSizeJump between two checks (an unstable explicit step grows
// geometrically) or by kBlowUpFactor over a stage (a too-large step drifts the scale), means the
// scheme failed.
constexpr double kBlowUpFactor = 10;
constexpr double kSizeJump = 2;

void validate(const FlowOptions& o) {
  auto bad = [](const std::string& what) { throw InvalidInputError("fair: " + what); };
  if (!(o.stepFactor > 0)) bad("stepFactor must be > 0");
  if (!(o.driftFactor >= 0)) bad("driftFactor must be >= 0");
  if (!(o.bilaplacianStep > 0 && o.bilaplacianStep < 0.5)) bad("bilaplacianStep must be in (0, 0.5)");
  if (!(o.energyTolerance >= 0) || !(o.subdivisionTolerance >= 0)) bad("tolerances must be >= 0");
  if (o.subdivisionLevels < 0 || o.subdivisionLevels > 8) bad("subdivisionLevels must be in [0, 8]");
  if (!(o.targetEdgeLength >= 0)) bad("targetEdgeLength must be >= 0");
  if (o.maxSteps < 0 || !(o.maxSeconds >= 0)) bad("maxSteps and maxSeconds must be >= 0");
  if (o.checkInterval < 1) bad("checkInterval must be >= 1");
}

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace

FlowReport fair(TriMesh& mesh, std::vector<std::uint8_t>* faceSelected, const FlowOptions& opt) {
  validate(opt);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

  std::vector<std::uint8_t> selection = faceSelected ? *faceSelected : std::vector<std::uint8_t>{};
  if (!selection.empty() && selection.size() != mesh.faces.size())
    throw InvalidInputError("fair: the selection has " + std::to_string(selection.size()) + " entries for " +
                            std::to_string(mesh.faces.size()) + " faces");
  std::unique_ptr<BoundarySlider> slider;
  if (opt.boundary == BoundaryMode::Slide)
    slider = std::make_unique<BoundarySlider>(Topology(mesh.vertexCount(), mesh.faces), mesh.positions);

  FlowReport report;
  double time = 0;
  bool stopped = false;
  for (int level = 0;; ++level) {
    FlowState state(mesh, selection, opt, slider.get());
    if (state.roles().freeCount == 0 && state.roles().slidingCount == 0) {
      throw InvalidInputError(
          "fair: no vertex can move (a moving vertex needs all its faces selected and, with a fixed "
          "boundary, must be at least two rings away from the boundary)");
    }
    const bool refineLater = level < opt.subdivisionLevels &&
                             (opt.targetEdgeLength <= 0 || state.geometry().meanEdgeLength > opt.targetEdgeLength);
    const double tolerance = refineLater ? opt.subdivisionTolerance : opt.energyTolerance;
    const double stageStart = elapsed();
    double energy = state.energy();
    if (level == 0) {
      report.energyInitial = energy;
      report.history.push_back({0, 0, 0, energy});
    }
    const double blowUp = kBlowUpFactor * std::max(std::abs(energy), 1.0);
    const double startEdge = state.geometry().meanEdgeLength;
    double checkpointEdge = startEdge;
    std::vector<Vec3> checkpoint = state.mesh().positions;
    long long checkpointStep = report.steps;
    double lastEnergy = energy, lastTime = time;
    FlowStage stage;
    stage.level = level;
    stage.vertices = state.mesh().vertexCount();
    stage.faces = state.mesh().faceCount();

    auto diverged = [&](const std::string& what) {
      state.setPositions(checkpoint);
      mesh.positions = checkpoint;
      report.stop = StopReason::Diverged;
      report.seconds = elapsed();
      stage.seconds = report.seconds - stageStart;
      report.stages.push_back(stage);
      throw FlowDivergedError("fair: the flow diverged at step " + std::to_string(report.steps) + " (" + what +
                                  "); restored the state of step " + std::to_string(checkpointStep) +
                                  ". Try a smaller step factor.",
                              report);
    };

    while (true) {
      if (report.steps >= opt.maxSteps) { report.stop = StopReason::MaxSteps; stopped = true; break; }
      if (opt.maxSeconds > 0 && elapsed() >= opt.maxSeconds) { report.stop = StopReason::MaxSeconds; stopped = true; break; }
      try {
        time += state.explicitStep();
      } catch (const NumericalError& e) {
        diverged(e.what());
      }
      ++report.steps;
      ++stage.steps;
      if (stage.steps % opt.checkInterval != 0) continue;

      energy = state.energy();
      if (!std::isfinite(energy)) diverged("non-finite energy");
      if (energy > blowUp) diverged("energy rose from " + fmt(lastEnergy) + " to " + fmt(energy));
      // E is scale-invariant, so an exploding mesh can keep a moderate E: watch its size too. A
      // closed surface may legitimately drift in scale (a zero mode of E), but slowly: an unstable
      // explicit step grows geometrically, check after check.
      const double edge = state.geometry().meanEdgeLength;
      const double jump = edge / checkpointEdge, drift = edge / startEdge;
      if (!(jump < kSizeJump && jump > 1 / kSizeJump))
        diverged("the mean edge length changed by a factor " + fmt(jump) + " since the last check");
      if (!(drift < kBlowUpFactor && drift > 1 / kBlowUpFactor))
        diverged("the mean edge length changed by a factor " + fmt(drift) + " since the stage began");
      checkpointEdge = edge;
      checkpoint = state.mesh().positions;
      checkpointStep = report.steps;
      report.minLambda = std::min(report.minLambda, state.lambda());
      report.history.push_back({report.steps, time, elapsed(), energy});
      if (opt.progress && !opt.progress({level, report.steps, energy, state.lambda(), elapsed()})) {
        report.stop = StopReason::Cancelled;
        stopped = true;
        break;
      }
      // Relative energy change per unit of normalised time t/A² (A the moving region's area):
      // independent of the model's scale and of the step size.
      const double area = state.activeArea();
      const double dtHat = (time - lastTime) / (area * area);
      const double rate = (lastEnergy - energy) / (std::max(std::abs(energy), 1.0) * dtHat);
      if (std::abs(rate) < tolerance) break;
      lastEnergy = energy;
      lastTime = time;
    }
    mesh.positions = state.mesh().positions;
    stage.energy = state.energy();
    stage.seconds = elapsed() - stageStart;
    report.stages.push_back(stage);
    report.energyFinal = stage.energy;
    if (stopped || !refineLater) break;
    subdivideMidpoint(mesh, selection.empty() ? nullptr : &selection);
  }
  if (faceSelected && !faceSelected->empty()) *faceSelected = selection;
  report.seconds = elapsed();
  if (report.history.back().step != report.steps) report.history.push_back({report.steps, time, report.seconds, report.energyFinal});
  return report;
}

}  // namespace elastica
