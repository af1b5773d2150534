// SPDX-License-Identifier: GPL-3.0-or-later
// Options and results of the fairing flows (paper §2–3). One options struct and one enum serve
// the three flows and, later, both integrators.
#pragma once

#include <elastica/curvature.h>
#include <elastica/errors.h>
#include <elastica/geometry.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace elastica {

enum class FlowType {
  /// F = −Δ_B H − 2H(H² − K) (paper eq. 1.5): gradient descent of ∫(k1² + k2²); converges to
  /// elastica (Willmore) surfaces — round spheres, Clifford tori.
  Elastica,
  /// F = −Δ_B H (paper eq. 3.1): keeps the volume, converges to constant mean curvature.
  LaplacianOfMeanCurvature,
  /// P ← P − τ U0²(P), the equal-weight bi-umbrella (paper §3): shrinks, connectivity-dependent.
  Bilaplacian,
};

/// How a flow advances in time.
enum class Scheme {
  /// The paper's explicit Euler step, τ = stepFactor · A_min² (stable, but the number of steps
  /// grows like the square of the vertex count).
  Explicit,
  /// Linearly implicit in the stiff fourth-order part (the paper's future work, §4):
  /// (M + τ/2 C M⁻¹ C) δ = τ M F for the normal displacement δ, everything else lagged; adaptive
  /// τ, a step accepted only if the energy does not rise, no face flips and no vertex jumps.
  /// Same fixed points as the explicit scheme (δ = 0 iff F = 0). Elastica and Laplacian of H.
  SemiImplicit,
  /// Linearly implicit in the positions themselves (flow/vector_integrator.h):
  /// (M + τ/2 C M⁻¹ C) δ = −τ/4 ∂W/∂X with the exact gradient of the discrete bending energy W
  /// (= E where Δ_B X is normal), one factorisation and three right-hand sides per step. Vertices
  /// move tangentially as well, so meshes stay even with the connectivity kept; every step is a
  /// descent direction, so τ grows to the region's own scale. Asked of a comparison flow, fair()
  /// runs the Laplacian-of-H flow semi-implicit and the bilaplacian flow explicit instead.
  Vector,
  /// Vector, or semi-implicit where the vector scheme cannot take its first step
  /// (docs/options.md). FlowReport::scheme says which ran.
  Automatic,
};

/// How vertices on the mesh boundary behave.
enum class BoundaryMode {
  /// Boundary vertices and their neighbours stay put: position and tangent plane clamped (G¹).
  Fixed,
  /// Boundary vertices slide along the original boundary polyline, equalising boundary edges; the
  /// rest of the mesh flows.
  Slide,
};

/// The operators of a fairing amount's filter (FlowOptions::amountOperators).
enum class AmountOperators {
  /// The input's cotangent weights and FlowOptions::area vertex areas (default): exact on a fair mesh.
  Cotangent,
  /// Uniform weights 1/√3 (an equilateral triangle's cotangent weight) and areas proportional to
  /// the vertex's faces (each (√3/4)·ℓ̄²/3, ℓ̄ the mean edge): on a noisy scan the cotangent weights
  /// and mixed areas are built from the noise (docs/options.md, "The default amount").
  Graph,
};

/// Why a run stopped.
enum class StopReason {
  Converged,   ///< the energy plateau
  Stalled,     ///< semi-implicit: no step size lowers the energy any more (a noise floor, or stuck)
  MaxSteps,
  MaxSeconds,
  Cancelled,
  Diverged,
  /// A comparison flow (bilaplacian, Laplacian of H) shrank the mesh: its mean edge length halved
  /// between two checks or fell to a tenth of the stage's start. The mesh is the last state.
  Shrunk,
  /// The elastica flow would go on lowering the energy only by making the surface cross itself
  /// (a knotted tube swelling into itself): every step the embedding guard allowed had shrunk to
  /// 1e-4 of the stage's largest. The mesh is the last state, which does not cross itself.
  SelfContact,
  /// FlowOptions::featureSize: the flow ran for the time that damps ripples of that size.
  FeatureSize,
  /// fair(mesh, region, …): no state the run reached passed the output checks (a manifold mesh, no
  /// vertices at one point, no new crossing faces, the faces off the region bit for bit, the
  /// region's energy not above its start); the input came back unchanged. FlowReport::refusedBecause
  /// says what failed. fair(mesh, …) on a whole mesh (to the limit shape, remeshing on): its output
  /// crossed itself where the input did not, or no state of the run was kept (the output would be
  /// the input); the input came back.
  Unchanged,
};

/// Whether a run ended at one of its caller's limits (FlowOptions::maxSteps, maxSeconds, or the
/// progress callback's cancel) rather than by its own stop.
inline bool stoppedAtALimit(StopReason stop) {
  return stop == StopReason::MaxSteps || stop == StopReason::MaxSeconds || stop == StopReason::Cancelled;
}

/// Progress of a run, given to FlowOptions::progress.
struct FlowProgress {
  int level = 0;          ///< subdivision level of the current stage (0 = input resolution)
  long long step = 0;     ///< steps so far, all stages
  double energy = 0;      ///< total curvature energy of the moving region
  double lambda = 1;      ///< the paper's λ (1 unless H2KTreatment::PaperLambda)
  double seconds = 0;     ///< wall time so far
};

/// Options of fair() (one line each: what, unit, default). Why each default is what it is, with
/// the measurements behind it: docs/options.md.
struct FlowOptions {
  FlowType flow = FlowType::Elastica;  ///< which flow; default the elastica flow
  /// Time integration; default Automatic. The Laplacian-of-H flow runs semi-implicit and the
  /// bilaplacian flow explicit whatever is asked (FlowReport::scheme says which ran).
  Scheme scheme = Scheme::Automatic;
  VertexArea area = VertexArea::Mixed;  ///< vertex area of the operators; default Meyer's mixed area
  CurvatureOptions curvature;           ///< H² − K < 0: clamped by default, or the paper's λ
  BoundaryMode boundary = BoundaryMode::Fixed;  ///< boundary vertices; default fixed with the next ring (G¹)

  /// Flip non-Delaunay edges among moving vertices at every check (positions untouched); default off.
  bool flipEdges = false;

  /// Vector and semi-implicit schemes: the mesh-quality stages around the flow (a working-resolution
  /// floor of 100 + 1,000·genus moving vertices, isotropic and curvature-adaptive remeshing of the
  /// moving region, Delaunay flips, the embedding guard); fixed vertices and their faces are never
  /// rewritten. Default on; off keeps the connectivity (but for flipEdges and subdivision).
  bool remesh = true;

  bool tangentialDrift = true;     ///< the tangential drift ε·T (paper eq. 2.5); default on
  double stepFactor = 1.0 / 150;   ///< explicit step τ = stepFactor · A_min² (dimensionless); default 1/150 (paper)
  double driftFactor = 12;         ///< drift ε = driftFactor · A_min (dimensionless); default 12 (paper)
  double bilaplacianStep = 0.05;   ///< bilaplacian step (dimensionless, stable below 0.5); default 0.05

  /// Stop at the energy plateau: relative energy change per unit of normalised time t/A² (A the
  /// moving region's area) below this; default 0.05. The vector scheme stops on the shape instead.
  double energyTolerance = 0.05;
  double subdivisionTolerance = 0.05;  ///< subdivide (if levels remain) when the same rate is below this; default 0.05
  int subdivisionLevels = 0;           ///< 1-to-4 subdivisions, coarse to fine (paper §2), 0..8; default 0
  double targetEdgeLength = 0;         ///< stop subdividing at this mean edge length (length; 0: no target); default 0

  /// A fairing amount (length; 0: flow until converged): run the flow's principal part −½Δ²u for
  /// t = 2 ln(100) (featureSize/2π)⁴, in which ripples of that wavelength lose 99 % of their height, then stop with
  /// StopReason::FeatureSize (docs/options.md). Elastica and Laplacian-of-H flows. Default 0.
  double featureSize = 0;
  /// The operators of featureSize's filter; default the mesh's cotangents. Not an option of any
  /// face: every face's run (app's runFairing) sets it from the mesh, Graph for a rough scan
  /// (app/fairing_amount.h), whatever the amount. Graph also twices the filter: it runs again on
  /// what it took away, which is added back (docs/options.md, "The default amount").
  AmountOperators amountOperators = AmountOperators::Cotangent;

  /// Step limit over all stages; default none (the largest count; every face shows it as 0).
  long long maxSteps = std::numeric_limits<long long>::max();
  double maxSeconds = 0;           ///< wall-time limit (seconds; 0: none); default 0
  int checkInterval = 100;         ///< explicit: steps between energy-rate checks and checkpoints; default 100

  /// Semi-implicit: stop when E changed by less than this (relative) over the last 10 accepted steps; default 1e-6.
  double plateauTolerance = 1e-6;
  /// Semi-implicit: also stop once a step at the scale of the whole moving region (τ ≥ A²/50)
  /// moves no vertex along its normal by more than this many mean edge lengths (0: off); default 0.
  double shapeTolerance = 0;
  int driftPasses = 2;  ///< semi-implicit: tangential drift passes after an accepted step; default 2

  /// Called at every check; return false to cancel (the mesh keeps its last good state).
  std::function<bool(const FlowProgress&)> progress;
};

/// One stage of the coarse-to-fine schedule.
struct FlowStage {
  int level = 0;
  /// The mesh the stage flowed: the whole mesh, or for fair(mesh, region, …) the piece around the
  /// region that the run works on (fairing.h).
  int vertices = 0, faces = 0;
  long long steps = 0;
  double energy = 0;   ///< at the end of the stage
  double seconds = 0;
};

/// One point of the energy history (every check).
struct EnergySample {
  long long step = 0;
  double time = 0;     ///< flow time Σ τ (length⁴; for the bilaplacian, Σ of its dimensionless step)
  double seconds = 0;  ///< wall time
  double energy = 0;
};

/// fair(mesh, region, …): a region's result is resolved when its energy over its moving vertices
/// rises by at most this fraction when the region is Loop-subdivided once
/// (FlowReport::regionResolutionGap). Wider than a whole mesh's 2 %: Loop's masks pull a curved
/// region in against its rim, which stays (a smooth cap of a 2,562-vertex sphere reads +2.4 %),
/// while the vector scheme's faceted lids read far above it (docs/decisions.md, "Regions").
inline constexpr double kRegionResolvedGap = 0.1;

struct FlowReport {
  double energyInitial = 0, energyFinal = 0;
  long long steps = 0;          ///< steps taken (semi-implicit: attempts, accepted or not)
  long long rejectedSteps = 0;  ///< semi-implicit attempts rejected (τ halved)
  /// FlowOptions::remesh: subdivisions made before the first flow (the working-resolution floor),
  /// isotropic remeshings of the moving region, and steps rejected because faces would cross.
  int preSubdivisions = 0, remeshings = 0;
  /// Subdivision levels of a coarse start: a large closed mesh remeshed at 2^k its edge length,
  /// flowed there, and subdivided back (0: it flowed at its own resolution).
  int coarseStartLevels = 0;
  /// FlowOptions::remesh: the most vertices the whole mesh may have at the run's finest level, set
  /// before the first flow step: the moving vertices after the first remeshing plus what
  /// curvature-adaptive remeshing of a fair shape of the region's genus adds, ×4 per level to come;
  /// remeshing never goes beyond it (0: no remeshing, the input's vertices and subdivisions).
  long long vertexBudget = 0;
  /// Tangential relaxation passes that untangled a jittered moving region before the vector
  /// scheme's flow (0: the region was not tangled, or a remeshing resampled it).
  int untanglePasses = 0;
  long long crossingRejections = 0;
  /// Reflows' curvature-adaptive remeshings that were tried and undone (they made faces cross,
  /// stacked vertices or left a degenerate corner): the stage after one flowed the mesh as it was.
  int remeshingsRefused = 0;
  /// The input's faces already crossed: the embedding guard was off (nothing to keep).
  bool inputSelfIntersects = false;
  double seconds = 0;
  double minLambda = 1;
  StopReason stop = StopReason::Converged;
  /// The scheme that ran (Scheme::Automatic resolved; the comparison flows' own).
  Scheme scheme = Scheme::Vector;
  std::vector<FlowStage> stages;
  std::vector<EnergySample> history;
  /// fair(mesh, region, …): the region's faces in the output mesh, ascending (after subdivision,
  /// the children of its faces). Empty when the whole mesh was faired.
  std::vector<int> regionFaces;
  /// fair(mesh, region, …): the energy Σ (4H² − 2K) A over the vertices of the region's faces (the
  /// region and its fixed rings) in the input and in the output, each at its own resolution; the
  /// after is never above the before. NaN when the whole mesh was faired.
  double regionEnergyBefore = std::numeric_limits<double>::quiet_NaN();
  double regionEnergyAfter = std::numeric_limits<double>::quiet_NaN();
  /// fair(mesh, region, …) run to its limit shape by the default scheme: how much the region's
  /// energy over its moving vertices rises when the region is Loop-subdivided once, relative
  /// (flow/region_resolution.h); above kRegionResolvedGap the mesh does not resolve the surface it stands for,
  /// and the stop is not `converged`. NaN when not measured.
  double regionResolutionGap = std::numeric_limits<double>::quiet_NaN();
  /// fair(mesh, region, …): 2 when the default scheme's result (or its first attempts, a probe)
  /// did not resolve the region and the semi-implicit scheme was run from the input too (the
  /// report is the run that came back, its steps and seconds all runs'), else 1.
  int regionRuns = 1;
  /// fair(mesh, region, …): what the run's last state failed, in words (empty if it came back).
  std::string refusedBecause;
  /// fair(mesh, region, …) whose last state failed: the stage (0-based, FlowReport::stages) whose
  /// end state came back instead, the last that passed; -1 with StopReason::Unchanged (none passed:
  /// the input came back) and when the last state came back.
  int keptStage = -1;
};

/// Thrown when a flow diverges; carries the report of the run up to the failure
/// (stop = StopReason::Diverged), so a caller can still write it.
class FlowDivergedError : public NumericalError {
 public:
  FlowDivergedError(const std::string& what, FlowReport report) : NumericalError(what), report_(std::move(report)) {}
  const FlowReport& report() const { return report_; }

 private:
  FlowReport report_;
};

}  // namespace elastica
