// Options and results of the fairing flows (paper §2–3). One options struct and one enum serve
// the three flows and, later, both integrators.
#pragma once

#include <elastica/curvature.h>
#include <elastica/errors.h>
#include <elastica/geometry.h>

#include <functional>
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
  /// Vector where the moving region has at least kVectorVerticesPerHandle · (genus + 1) vertices
  /// (any genus-0 region, a disk included), semi-implicit below: on handles resolved by few edges
  /// the vector scheme's tangential freedom finds discrete states below the continuum's minimum
  /// (a genus-2 cage at 1,213 vertices: E 104.6 where the genus-2 minimiser has 112.8; a tube
  /// torus at 494 vertices: E 57.7 where no torus goes below 8π² ≈ 79), which it does not at
  /// 6,577 and 15,536 vertices (112.83, 78.93). At 1,000 vertices per handle it still stalled on
  /// the genus-2 and genus-3 block cages (--subdivide 3: 3,034 and 4,088 vertices, 594 and 2,622
  /// attempts, 20 and 94 s), where the semi-implicit scheme converged at E 112.78 and 143.04 in
  /// 622 and 801 attempts; a thin ring at 3,072 per handle converges (E 78.85), knot1 at 1,600
  /// stops at its self-contact (the semi-implicit scheme stalls there). FlowReport::scheme says
  /// which ran.
  Automatic,
};

/// Scheme::Automatic's threshold (see there).
inline constexpr int kVectorVerticesPerHandle = 1500;

/// How vertices on the mesh boundary behave.
enum class BoundaryMode {
  /// Boundary vertices and their neighbours stay put: position and tangent plane clamped (G¹).
  Fixed,
  /// Boundary vertices slide along the original boundary polyline, equalising boundary edges; the
  /// rest of the mesh flows.
  Slide,
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
};

/// Progress of a run, given to FlowOptions::progress.
struct FlowProgress {
  int level = 0;          ///< subdivision level of the current stage (0 = input resolution)
  long long step = 0;     ///< steps so far, all stages
  double energy = 0;      ///< total curvature energy of the moving region
  double lambda = 1;      ///< the paper's λ (1 unless H2KTreatment::PaperLambda)
  double seconds = 0;     ///< wall time so far
};

struct FlowOptions {
  FlowType flow = FlowType::Elastica;
  /// Automatic by default, the vector scheme on everything but coarse meshes with handles: whole
  /// scans that the semi-implicit scheme left at its time limit (cow, dino, bull) converge to round
  /// spheres in under 200 attempts (docs/benchmarks.md).
  /// The Laplacian-of-H flow runs semi-implicit, the bilaplacian flow explicit (fair() says so if
  /// asked otherwise).
  Scheme scheme = Scheme::Automatic;
  VertexArea area = VertexArea::Mixed;
  CurvatureOptions curvature;  ///< H² − K treatment (clamp by default, or the paper's λ)
  BoundaryMode boundary = BoundaryMode::Fixed;

  /// Dynamic connectivity (the paper's future work [7]), lightly: at every check, flip the
  /// non-Delaunay edges among moving vertices. Positions are untouched; faces change.
  bool flipEdges = false;
  /// With flipEdges: look for edges to flip at every flipInterval-th check only. Each flip changes
  /// the semi-implicit system's sparsity pattern, which is then built and analysed again:
  /// flipping at every step (flips on 31 of 41 steps), that was 26 % of a 406-edge hole's fill.
  int flipInterval = 1;

  /// Semi-implicit scheme: mesh quality as stages of the pipeline (the paper's future work,
  /// dynamic connectivity). Before the first flow, the mesh is subdivided (within
  /// subdivisionLevels) until at least 100 + 1,000·genus vertices move; before the first stage, the
  /// faces whose vertices all move are remeshed isotropically (split, collapse, flip, relax; the
  /// vertex count stays about the same); after a stage that left an angle below 20° or a vertex
  /// whose curvature κ and edge length ℓ have κℓ > 0.6 (a neck the energy cannot see), they are
  /// remeshed again, finer where κ is large (ℓ ≈ 0.4/κ), and flowed again (twice at most);
  /// after every accepted step, non-Delaunay edges among moving vertices are flipped; and no step
  /// or remeshing that makes faces cross is accepted when the input's did not (the embedding
  /// guard). Fixed vertices and every face touching one are never rewritten. Off: the mesh keeps
  /// its connectivity (but for flipEdges and subdivision). The explicit scheme ignores it.
  bool remesh = true;

  /// Tangential drift ε·T (paper eq. 2.5): area-weighted bi-umbrella, keeps triangles even.
  bool tangentialDrift = true;
  /// τ = stepFactor · A_min² (paper: 1/150; stable up to about 1/3 on icospheres).
  double stepFactor = 1.0 / 150;
  /// ε = driftFactor · A_min (paper: 12).
  double driftFactor = 12;
  /// Bilaplacian step (dimensionless: U0² scales like length, stable below 0.5).
  double bilaplacianStep = 0.05;

  /// Stop at the energy plateau: when the relative energy change per unit of normalised time
  /// t / A² (A the moving region's area, so the measure depends on neither scale nor resolution)
  /// falls below this. On a noisy 642-vertex sphere 0.05 leaves a radius spread under 0.5 %;
  /// 0.02 took 4× the steps for a spread of 0.26 % (the last slow mode is a mesh redistribution
  /// that changes E by ~1e-6 relative per 10,000 steps). The explicit scheme measures it every
  /// checkInterval steps, the semi-implicit one over its last 10 accepted steps; the vector scheme
  /// stops on the shape instead (its normal motion over the slowest mode's time), not on this.
  double energyTolerance = 0.05;
  /// Subdivide (if levels remain) when the same rate falls below this (near steady state).
  double subdivisionTolerance = 0.05;
  /// Number of 1-to-4 subdivisions (coarse-to-fine, paper §2).
  int subdivisionLevels = 0;
  /// Stop subdividing once the mean edge length is at or below this (0: no target).
  double targetEdgeLength = 0;

  /// A fairing amount (a length, in the mesh's units; 0: off, flow until converged). The flow's
  /// principal part u_t = −½ Δ²u runs for the time t = 2 (featureSize / 2π)⁴ and stops with
  /// StopReason::FeatureSize. It damps a ripple of wavelength λ like exp(−½ (2π/λ)⁴ t): ripples of
  /// featureSize lose 1/e of their height, ripples of a third of it vanish (e⁻⁸¹), shapes five
  /// times larger keep all but 1/600 of theirs, and a sphere of radius R shrinks by
  /// 4R (featureSize / 2πR)⁴. With the vector scheme (Automatic's choice under an amount): four
  /// linearly implicit steps with the operators of the mesh as given, its vertices and
  /// connectivity kept, no step refused (the full flow's nonlinear terms act on the shape's own
  /// scale, which the amount leaves alone, and on a noisy scan they read the noise as curvature).
  /// With the explicit or semi-implicit scheme, or the Laplacian-of-H flow: that scheme's steps of
  /// the full flow, at most t/4, without the first remeshing. Not for the bilaplacian flow (its
  /// time has no length unit).
  double featureSize = 0;

  long long maxSteps = 2'000'000;  ///< over all stages
  double maxSeconds = 0;           ///< wall-time limit; 0 means none
  int checkInterval = 100;         ///< explicit: steps between energy-rate checks and checkpoints

  /// Semi-implicit: stop when E changed by less than this (relative) over the last 10 accepted steps.
  double plateauTolerance = 1e-6;
  /// Semi-implicit: also stop once the shape has settled, when an accepted step is implicit at the
  /// scale of the whole moving region (τ ≥ A²/50, A its area: even its slowest bending mode
  /// relaxes within the step, so δ approximates the remaining distance to the fixed point) and
  /// moved no vertex along its normal by more than this times the mean edge length. 0 turns it
  /// off (`fair`'s default). After that point the energy still falls slowly, for hundreds of
  /// steps, while the tangential drift evens out the vertices and the surface follows by less
  /// than 10⁻⁴ ℓ per step (bunny flank: 21 steps instead of 273, the same distances to the
  /// removed surface within 0.04 % of the diagonal); a hole fill (default 10⁻³) does not wait.
  double shapeTolerance = 0;
  /// Semi-implicit: the first step is a tenth of the moving region's shape scale (τ = A²/500)
  /// instead of 0.05 ℓ⁴. For a start that is smooth already (a hole's bi-Laplace patch), where
  /// growing τ by ×1.5 from the mesh's scale only ramps up: a 200-edge hole in a 44k-vertex scan
  /// took 62 steps, 24 from the shape scale, to the same energy within 0.2 %. A step too large is
  /// rejected and halved as any other.
  bool startAtShapeScale = false;
  /// Semi-implicit: a step is rejected if a vertex moves along its normal by more than this many
  /// of its mean edge lengths (folds, the energy and crossings judge every step too). 0.5 made
  /// the steps a torus needs grow with its resolution. The distance a hole's patch travels from
  /// its bi-Laplace start grows with the hole, in edge lengths (its steps' largest moves summed
  /// to about 17 on a 406-edge hole, at up to 1.9 a step), so the fill allows more
  /// (HoleFillOptions::defaultFillFlow).
  double maxJump = 2;
  /// Semi-implicit: a step that would move a vertex farther than maxJump is shortened to that
  /// distance (every vertex's displacement scaled by the same factor) instead of rejected, and τ
  /// is kept. The solve's direction is a descent direction whatever the length taken along it, so
  /// the energy test still judges the shortened step; a rejected step cost a factorisation, and
  /// the ceiling it left behind made τ grow by ×1.2 instead of ×1.5 a step for the rest of the run
  /// (a 794-edge hole: 5 rejections, then 26 steps from τ = A²/16,000 to A²/125).
  /// Off for `fair`; the fill turns it on (HoleFillOptions::defaultFillFlow).
  bool shortenJumps = false;
  /// Semi-implicit: tangential drift passes (ε = driftFactor · A_min each) after an accepted step.
  int driftPasses = 2;

  /// Called at every check; return false to cancel (the mesh keeps its last good state).
  std::function<bool(const FlowProgress&)> progress;
};

/// One stage of the coarse-to-fine schedule.
struct FlowStage {
  int level = 0;
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

struct FlowReport {
  double energyInitial = 0, energyFinal = 0;
  long long steps = 0;          ///< steps taken (semi-implicit: attempts, accepted or not)
  long long rejectedSteps = 0;  ///< semi-implicit attempts rejected (τ halved)
  /// FlowOptions::remesh: subdivisions made before the first flow (the working-resolution floor),
  /// isotropic remeshings of the moving region, and steps rejected because faces would cross.
  int preSubdivisions = 0, remeshings = 0;
  /// Tangential relaxation passes that untangled a jittered moving region before the vector
  /// scheme's flow (0: the region was not tangled, or a remeshing resampled it).
  int untanglePasses = 0;
  long long crossingRejections = 0;
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
