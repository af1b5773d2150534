// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/schedule.h"

#include <algorithm>
#include <cmath>

namespace elastica {

bool fallsBackToSemiImplicit(Scheme scheme, bool automatic, bool firstStage, long long steps) {
  return automatic && scheme == Scheme::Vector && firstStage && steps == 0;
}

bool plateauConfirmed(double energy, double previousEnergy) {
  return std::abs(energy - previousEnergy) <= kConfirmedPlateau * std::abs(energy);
}

VectorReflows::Verdict VectorReflows::judge(double energy, long long steps, int reflows) {
  if (steps == 0) return Stop;
  if (energy < (1 - kConfirmedPlateau) * best_) {
    best_ = energy;
    idle_ = 0;
    return reflows < kMaxReflows ? Again : Stop;
  }
  if (reflows > 0 && energy <= (1 + kConfirmedPlateau) * best_) return Converged;
  best_ = std::min(best_, energy);
  return ++idle_ < kIdleReflows && reflows < kMaxReflows ? Again : Stop;
}

bool finalApproach(Scheme scheme, bool quality, bool stopped, StopReason stop) {
  return scheme == Scheme::Vector && !quality && !stopped && stop == StopReason::Converged;
}

NextStage Schedule::next(const StageVerdict& verdict, const ScheduleContext& context, StopReason& stop) {
  if (fallsBackToSemiImplicit(context.scheme, context.automatic, context.firstStage, verdict.steps) &&
      !context.stopped()) {
    stop = StopReason::Converged;
    return NextStage::FallBack;
  }
  bool meshBound = verdict.meshBound();
  if (context.scheme == Scheme::SemiImplicit && meshBound && reflows_ > 0 &&
      plateauConfirmed(verdict.energy, context.previousEnergy)) {
    meshBound = false;
    stop = StopReason::Converged;
  }
  // A limit reached just as the stage converged stops the run before it refines: a finer mesh
  // costs four times the memory and work, and its stage could not take a step.
  if (context.stopped()) return NextStage::Stop;
  bool reflow = reflows_ < kMaxReflowsPerLevel;
  if (context.quality && context.scheme == Scheme::Vector && meshBound) {
    const VectorReflows::Verdict judged = vectorReflows_.judge(verdict.energy, verdict.steps, reflows_);
    reflow = judged == VectorReflows::Again;
    if (judged == VectorReflows::Converged) {
      meshBound = false;
      stop = StopReason::Converged;
    }
  }
  if (context.quality && reflow && (meshBound || context.needsRemeshing())) {
    ++reflows_;
    stop = StopReason::Converged;  // the next stage decides
    return NextStage::Reflow;
  }
  if (!context.quality && context.scheme == Scheme::Vector && meshBound && reflows_ < kMaxReflowsPerLevel) {
    ++reflows_;
    stop = StopReason::Converged;
    return NextStage::Untangle;
  }
  if (!context.refineLater) return NextStage::Stop;
  reflows_ = 0;
  vectorReflows_ = VectorReflows{};
  stop = StopReason::Converged;  // the next stage decides
  return NextStage::Refine;
}

}  // namespace elastica
