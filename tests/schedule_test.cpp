// SPDX-License-Identifier: GPL-3.0-or-later
// The schedule's rules (flow/schedule.h), each on its own, and Schedule::next on the sequences of
// verdicts that decide a run: reflows, refinements, the fall-back and the stop reasons.
#include "flow/schedule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace elastica {
namespace {

// A context whose queries answer as given and count how often they were asked.
struct Probe {
  bool stopped = false, needsRemeshing = false;
  int stoppedAsked = 0, remeshingAsked = 0;
  ScheduleContext context(Scheme scheme, bool quality, bool refineLater) {
    ScheduleContext c;
    c.scheme = scheme;
    c.quality = quality;
    c.refineLater = refineLater;
    c.stopped = [this] { return ++stoppedAsked, stopped; };
    c.needsRemeshing = [this] { return ++remeshingAsked, needsRemeshing; };
    return c;
  }
};

StageVerdict verdict(StageEnd end, long long steps, double energy) { return {end, steps, energy}; }

TEST(ScheduleRules, FallsBackOnlyWhenTheAutomaticVectorSchemeTookNoStepInTheFirstStage) {
  EXPECT_TRUE(fallsBackToSemiImplicit(Scheme::Vector, true, true, 0));
  EXPECT_FALSE(fallsBackToSemiImplicit(Scheme::Vector, false, true, 0));  // asked for by name
  EXPECT_FALSE(fallsBackToSemiImplicit(Scheme::Vector, true, false, 0));  // a later stage
  EXPECT_FALSE(fallsBackToSemiImplicit(Scheme::Vector, true, true, 1));
  EXPECT_FALSE(fallsBackToSemiImplicit(Scheme::SemiImplicit, true, true, 0));
}

TEST(ScheduleRules, PlateauIsConfirmedWithinHalfAPercentEitherWay) {
  EXPECT_TRUE(plateauConfirmed(100, 100));
  EXPECT_TRUE(plateauConfirmed(100, 100.5));
  EXPECT_TRUE(plateauConfirmed(100, 99.5));
  EXPECT_FALSE(plateauConfirmed(100, 100.6));
  EXPECT_FALSE(plateauConfirmed(100, 99.4));
  EXPECT_FALSE(plateauConfirmed(100, std::numeric_limits<double>::quiet_NaN()));  // no stage before
}

TEST(ScheduleRules, VectorReflowsGoOnWhileTheyLowerTheBestEnergy) {
  VectorReflows reflows;
  EXPECT_EQ(reflows.judge(200, 10, 0), VectorReflows::Again);
  EXPECT_EQ(reflows.judge(180, 10, 1), VectorReflows::Again);    // 10 % lower
  EXPECT_EQ(reflows.judge(180.5, 10, 2), VectorReflows::Converged);  // within 0.5 % of the best
}

TEST(ScheduleRules, VectorReflowsStopAfterIdleStagesOrAStageWithoutSteps) {
  VectorReflows idle;
  EXPECT_EQ(idle.judge(100, 10, 0), VectorReflows::Again);
  EXPECT_EQ(idle.judge(110, 10, 1), VectorReflows::Again);  // above the best: idle once
  EXPECT_EQ(idle.judge(120, 10, 2), VectorReflows::Again);  // twice
  EXPECT_EQ(idle.judge(130, 10, 3), VectorReflows::Stop);   // kIdleReflows in a row
  VectorReflows stuck;
  EXPECT_EQ(stuck.judge(100, 0, 0), VectorReflows::Stop);
  VectorReflows budget;
  EXPECT_EQ(budget.judge(100, 10, VectorReflows::kMaxReflows), VectorReflows::Stop);
}

TEST(ScheduleRules, FinalApproachOnlyAfterAConvergedVectorRunWithTheConnectivityKept) {
  EXPECT_TRUE(finalApproach(Scheme::Vector, false, false, StopReason::Converged));
  EXPECT_FALSE(finalApproach(Scheme::Vector, true, false, StopReason::Converged));   // remeshed
  EXPECT_FALSE(finalApproach(Scheme::Vector, false, true, StopReason::Converged));   // stopped
  EXPECT_FALSE(finalApproach(Scheme::Vector, false, false, StopReason::Stalled));
  EXPECT_FALSE(finalApproach(Scheme::SemiImplicit, false, false, StopReason::Converged));
}

TEST(Schedule, FallsBackBeforeAnythingElseAndSaysConverged) {
  Schedule schedule;
  Probe probe;
  ScheduleContext c = probe.context(Scheme::Vector, true, true);
  c.automatic = true;
  c.firstStage = true;
  StopReason stop = StopReason::Stalled;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 0, 50), c, stop), NextStage::FallBack);
  EXPECT_EQ(stop, StopReason::Converged);
  EXPECT_EQ(probe.remeshingAsked, 0);
  probe.stopped = true;  // a limit, not the mesh, left the stage without a step: no fall-back
  stop = StopReason::MaxSeconds;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 0, 50), c, stop), NextStage::Stop);
  EXPECT_EQ(stop, StopReason::MaxSeconds);
}

TEST(Schedule, ALimitStopsTheRunBeforeItRefines) {
  Schedule schedule;
  Probe probe;
  probe.stopped = true;
  StopReason stop = StopReason::MaxSteps;
  EXPECT_EQ(schedule.next(verdict(StageEnd::Settled, 5, 80), probe.context(Scheme::Vector, true, true), stop),
            NextStage::Stop);
  EXPECT_EQ(stop, StopReason::MaxSteps);
  EXPECT_EQ(probe.remeshingAsked, 0);
}

TEST(Schedule, SemiImplicitReflowsTwicePerLevelThenRefinesOrStops) {
  Schedule schedule;
  Probe probe;
  StopReason stop = StopReason::Stalled;
  // A stalled stage is remeshed and flowed again, twice at most.
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 30, 150), probe.context(Scheme::SemiImplicit, true, true), stop),
            NextStage::Reflow);
  EXPECT_EQ(stop, StopReason::Converged);
  EXPECT_EQ(schedule.reflows(), 1);
  ScheduleContext second = probe.context(Scheme::SemiImplicit, true, true);
  second.previousEnergy = 150;
  stop = StopReason::Stalled;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 30, 120), second, stop), NextStage::Reflow);  // 20 % lower
  stop = StopReason::Stalled;
  second.previousEnergy = 120;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 30, 110), second, stop), NextStage::Refine);
  EXPECT_EQ(schedule.reflows(), 0);  // a new level, a new budget
  // At the finest level the same stalled stage ends the run, and says so.
  ScheduleContext last = probe.context(Scheme::SemiImplicit, true, false);
  stop = StopReason::Stalled;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 30, 110), last, stop), NextStage::Reflow);
  stop = StopReason::Stalled;
  last.previousEnergy = 110;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 30, 100), last, stop), NextStage::Reflow);
  stop = StopReason::Stalled;
  last.previousEnergy = 100;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 30, 90), last, stop), NextStage::Stop);
  EXPECT_EQ(stop, StopReason::Stalled);
}

TEST(Schedule, AReflowWithinHalfAPercentConfirmsASemiImplicitPlateau) {
  Schedule schedule;
  Probe probe;
  StopReason stop = StopReason::Stalled;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 30, 113), probe.context(Scheme::SemiImplicit, true, false), stop),
            NextStage::Reflow);
  ScheduleContext c = probe.context(Scheme::SemiImplicit, true, false);
  c.previousEnergy = 113;
  stop = StopReason::Stalled;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 30, 112.8), c, stop), NextStage::Stop);
  EXPECT_EQ(stop, StopReason::Converged);
  EXPECT_EQ(probe.remeshingAsked, 1);  // confirmed: the mesh's fitness alone decides a reflow
}

TEST(Schedule, ASettledStageIsRemeshedOnlyIfItsMeshIsUnfit) {
  Schedule schedule;
  Probe probe;
  StopReason stop = StopReason::Converged;
  EXPECT_EQ(schedule.next(verdict(StageEnd::Settled, 30, 80), probe.context(Scheme::SemiImplicit, true, false), stop),
            NextStage::Stop);
  EXPECT_EQ(probe.remeshingAsked, 1);
  probe.needsRemeshing = true;
  EXPECT_EQ(schedule.next(verdict(StageEnd::Settled, 30, 80), probe.context(Scheme::SemiImplicit, true, false), stop),
            NextStage::Reflow);
  // Without remeshing (FlowOptions::remesh off, or the explicit scheme) nothing is remeshed.
  Probe off;
  off.needsRemeshing = true;
  EXPECT_EQ(schedule.next(verdict(StageEnd::Settled, 30, 80), off.context(Scheme::Explicit, false, true), stop),
            NextStage::Refine);
  EXPECT_EQ(off.remeshingAsked, 0);
}

TEST(Schedule, VectorReflowsFollowTheirOwnBudget) {
  Schedule schedule;
  Probe probe;
  StopReason stop = StopReason::Stalled;
  double energy = 300;
  for (int k = 0; k < 5; ++k, energy *= 0.9) {  // far more than two reflows while each lowers E
    stop = StopReason::Stalled;
    EXPECT_EQ(schedule.next(verdict(StageEnd::NeckFormed, 20, energy), probe.context(Scheme::Vector, true, false), stop),
              NextStage::Reflow);
  }
  stop = StopReason::Stalled;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 20, energy / 0.9), probe.context(Scheme::Vector, true, false), stop),
            NextStage::Stop);  // within 0.5 % of the best: converged
  EXPECT_EQ(stop, StopReason::Converged);
}

TEST(Schedule, VectorWithTheConnectivityKeptUntanglesTwiceAtMost) {
  Schedule schedule;
  Probe probe;
  StopReason stop = StopReason::Stalled;
  for (int k = 0; k < kMaxReflowsPerLevel; ++k) {
    stop = StopReason::Stalled;
    EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 20, 100), probe.context(Scheme::Vector, false, false), stop),
              NextStage::Untangle);
    EXPECT_EQ(stop, StopReason::Converged);
  }
  stop = StopReason::Stalled;
  EXPECT_EQ(schedule.next(verdict(StageEnd::MeshBound, 20, 100), probe.context(Scheme::Vector, false, false), stop),
            NextStage::Stop);
  EXPECT_EQ(stop, StopReason::Stalled);
  EXPECT_EQ(probe.remeshingAsked, 0);
}

}  // namespace
}  // namespace elastica
