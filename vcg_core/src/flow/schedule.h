// SPDX-License-Identifier: GPL-3.0-or-later
// The schedule of a fair() run (fairRegion, flow/fairing.cpp): what follows a flow stage. A stage
// ends with a verdict (StageVerdict); Schedule::next turns it into the next move: flow the same
// level again after a remeshing (Reflow) or, with the connectivity kept, an untangling
// (Untangle); refine to the next level (Refine); start over with the semi-implicit scheme
// (FallBack); or stop, with the report's stop reason saying why. Each rule is a named function
// below, with its test in tests/schedule_test.cpp; the measurements behind the rules are in
// docs/decisions.md ("The schedule's rules").
#pragma once

#include <elastica/flow.h>

#include <functional>
#include <limits>

namespace elastica {

/// How a flow stage ended.
enum class StageEnd {
  Settled,    ///< the shape settled, or the stage's own stop (report.stop) ended it
  MeshBound,  ///< the mesh, not the shape, held the flow back (report.stop says Stalled)
  NeckFormed, ///< MeshBound: a neck narrowed below what its edges resolve (vector scheme)
};

/// A stage's verdict: how it ended, its accepted steps and its output's energy.
struct StageVerdict {
  StageEnd end = StageEnd::Settled;
  long long steps = 0;
  double energy = 0;
  bool meshBound() const { return end != StageEnd::Settled; }
};

/// The run around a stage that just ended. The two queries are asked only when a rule needs them,
/// in the order the rules run: `stopped` may record a limit in the report's stop reason.
struct ScheduleContext {
  Scheme scheme = Scheme::Vector;  ///< the scheme the stage ran
  bool automatic = false;          ///< Scheme::Automatic was asked for
  bool quality = false;            ///< FlowOptions::remesh under an adaptive scheme
  bool firstStage = false;         ///< no stage ended before this one
  bool refineLater = false;        ///< a finer level is still to come
  /// The energy of the stage before (NaN if none).
  double previousEnergy = std::numeric_limits<double>::quiet_NaN();
  std::function<bool()> stopped;         ///< a limit or a cancellation ended the run
  std::function<bool()> needsRemeshing;  ///< the stage's mesh is unfit for the operators
};

enum class NextStage { Reflow, Untangle, Refine, FallBack, Stop };

/// A remeshed reflow's energy within this fraction of the energy before it confirms a plateau.
inline constexpr double kConfirmedPlateau = 0.005;
/// Reflows of one level: the semi-implicit scheme's, and the vector scheme's with the
/// connectivity kept (VectorReflows has its own budget).
inline constexpr int kMaxReflowsPerLevel = 2;

/// Scheme::Automatic starts over with the semi-implicit scheme where the vector scheme could take
/// no step in the run's first stage (and no limit stopped it: the caller checks that).
bool fallsBackToSemiImplicit(Scheme scheme, bool automatic, bool firstStage, long long steps);

/// A semi-implicit stage held back by the mesh, after a reflow, whose energy is within
/// kConfirmedPlateau of the stage before: the plateau is the shape's (converged).
bool plateauConfirmed(double energy, double previousEnergy);

/// The vector scheme's remeshed reflows of one level, for stages the mesh held back: flowed again
/// while each lowers the level's best energy by more than kConfirmedPlateau, at most kMaxReflows
/// times; a reflow within kConfirmedPlateau of the best confirms the plateau; kIdleReflows stages
/// in a row above it, or a stage that took no step, end the level.
class VectorReflows {
 public:
  static constexpr int kMaxReflows = 40, kIdleReflows = 3;
  enum Verdict { Again, Converged, Stop };
  Verdict judge(double energy, long long steps, int reflows);

 private:
  double best_ = std::numeric_limits<double>::infinity();
  int idle_ = 0;
};

/// After the last stage: the vector scheme's converged state on a region whose connectivity was
/// kept (no remeshing) gets a short semi-implicit approach from evened-out vertices.
bool finalApproach(Scheme scheme, bool quality, bool stopped, StopReason stop);

/// Turns each stage's verdict into the next move, keeping the per-level reflow counts.
class Schedule {
 public:
  /// The move after a stage; `stop` (the report's stop reason) is updated as the rules decide:
  /// Converged where a later stage decides or a plateau is confirmed.
  NextStage next(const StageVerdict& verdict, const ScheduleContext& context, StopReason& stop);
  /// Reflows of the current level so far.
  int reflows() const { return reflows_; }

 private:
  int reflows_ = 0;
  VectorReflows vectorReflows_;
};

}  // namespace elastica
