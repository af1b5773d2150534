// The fairing flows (paper §2–3) against analytic shapes: spheres stay round, noisy spheres become
// round, tori move toward the Clifford torus, energy decreases, and the scheme is scale-covariant.
#include "test_meshes.h"

#include <elastica/energy.h>
#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/shapes.h>
#include <elastica/subdivision.h>
#include "mesh/edge_flips.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <random>

using namespace elastica;

namespace {

struct RadiusStats {
  double mean = 0, min = 1e300, max = 0;
  double spread() const { return (max - min) / mean; }
};

RadiusStats radii(const TriMesh& m) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : m.positions) c += p;
  c /= m.vertexCount();
  RadiusStats s;
  for (const Vec3& p : m.positions) {
    const double r = (p - c).norm();
    s.mean += r;
    s.min = std::min(s.min, r);
    s.max = std::max(s.max, r);
  }
  s.mean /= m.vertexCount();
  return s;
}

// Each vertex moved radially by a uniform factor in [1 − a, 1 + a].
TriMesh radialNoise(TriMesh m, double a, unsigned seed) {
  shapes::addRadialNoise(m, a, seed);
  return m;
}

// Energy recomputed from scratch, independently of the flow's own bookkeeping.
double energyOf(const TriMesh& m) {
  const Topology t(m.vertexCount(), m.faces);
  const Geometry g = computeGeometry(t, m.positions);
  return totalCurvatureEnergy(t, g, computeCurvature(t, g, m.positions));
}

// R/r of a torus around z: half the sum and half the difference of the extreme distances from the axis.
double aspectRatio(const TriMesh& m) {
  double lo = 1e300, hi = 0;
  for (const Vec3& p : m.positions) {
    const double d = std::hypot(p.x(), p.y());
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return (hi + lo) / (hi - lo);
}

}  // namespace

TEST(Flow, RoundSphereStaysRound) {
  TriMesh m = shapes::icosphere(1.0, 3);
  const FlowReport r = fair(m, FlowOptions{});
  EXPECT_EQ(r.stop, StopReason::Converged);
  for (const Vec3& p : m.positions) EXPECT_NEAR(p.norm(), 1.0, 1e-3);
}

// 5 % radial noise on a 162-vertex icosphere, faired coarse to fine (one subdivision, 642
// vertices): round to 0.5 % and E within 2 % of 8π (the 642-vertex discretisation itself is
// 0.95 % below 8π).
TEST(Flow, NoisySphereBecomesRound) {
  TriMesh m = radialNoise(shapes::icosphere(1.0, 2), 0.05, 1);
  ASSERT_GT(radii(m).spread(), 0.08);
  FlowOptions opt;
  opt.subdivisionLevels = 1;
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Converged);
  ASSERT_EQ(r.stages.size(), 2u);
  EXPECT_EQ(m.vertexCount(), 642);
  EXPECT_LT(radii(m).spread(), 0.005);
  EXPECT_NEAR(energyOf(m), 8 * M_PI, 0.02 * 8 * M_PI);
  EXPECT_NEAR(r.energyFinal, energyOf(m), 1e-9 * energyOf(m));
}

// A torus of revolution R/r = 3 moves toward the Clifford torus R/r = √2 (E = 8π²) with E
// decreasing at every check. Full convergence takes ~N² explicit steps: this test checks the
// direction on a coarse torus; the semi-implicit integrator takes it all the way.
TEST(Flow, TorusMovesTowardCliffordTorus) {
  TriMesh m = shapes::torus(3, 1, 24, 8);
  FlowOptions opt;
  opt.energyTolerance = 0;
  opt.maxSteps = 40000;
  const FlowReport r = fair(m, opt);
  for (size_t k = 1; k < r.history.size(); ++k) EXPECT_LE(r.history[k].energy, r.history[k - 1].energy) << k;
  const double a = aspectRatio(m);
  EXPECT_LT(a, 2.5);
  EXPECT_GT(a, std::sqrt(2.0) * 0.95);
  EXPECT_LT(r.energyFinal, 0.8 * r.energyInitial);
}

// E between checks: never up for the elastica flow (its gradient-descent flow) nor, on this
// noisy sphere, for the Laplacian of H; the bilaplacian is not a descent of E and may raise it a
// little (measured: 0.4 % once) — allowed 1 % per check.
TEST(Flow, EnergyNonIncreasingOnNoisySphere) {
  const TriMesh noisy = radialNoise(shapes::icosphere(1.0, 2), 0.05, 2);
  for (FlowType flow : {FlowType::Elastica, FlowType::LaplacianOfMeanCurvature, FlowType::Bilaplacian}) {
    TriMesh m = noisy;
    FlowOptions opt;
    opt.flow = flow;
    opt.maxSteps = 20000;
    const FlowReport r = fair(m, opt);
    const double allowed = flow == FlowType::Bilaplacian ? 1e-2 : 1e-12;
    for (size_t k = 1; k < r.history.size(); ++k)
      EXPECT_LE(r.history[k].energy, r.history[k - 1].energy * (1 + allowed)) << int(flow) << " at " << k;
    EXPECT_LT(r.energyFinal, 0.7 * r.energyInitial) << int(flow);
  }
}

// The scheme is scale-covariant: τ ∝ length⁴, ε·T ∝ length, tolerances relative to the mean edge.
TEST(Flow, ScaleCovariance) {
  const TriMesh base = radialNoise(shapes::icosphere(1.0, 2), 0.05, 3);
  for (FlowType flow : {FlowType::Elastica, FlowType::LaplacianOfMeanCurvature, FlowType::Bilaplacian}) {
    FlowOptions opt;
    opt.flow = flow;
    opt.energyTolerance = 0;
    opt.maxSteps = 2000;
    TriMesh ref = base;
    fair(ref, opt);
    for (double s : {1e3, 1e-3}) {
      TriMesh m = test::scaled(base, s);
      const FlowReport r = fair(m, opt);
      EXPECT_EQ(r.steps, 2000);
      double worst = 0;
      for (int v = 0; v < m.vertexCount(); ++v) worst = std::max(worst, (m.positions[v] / s - ref.positions[v]).norm());
      EXPECT_LT(worst, 1e-6) << "flow " << int(flow) << " scale " << s;
    }
  }
}

// Outside the selection, and on the two rings around it, nothing moves: bit for bit.
TEST(Flow, FixedVerticesAreBitIdentical) {
  TriMesh m = shapes::grid(16, 16, 1.0);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (Vec3& p : m.positions) p.z() = u(rng);
  const TriMesh before = m;
  std::vector<std::uint8_t> selected(m.faceCount(), 0);
  for (int f = 0; f < m.faceCount(); ++f) {
    Vec3 c = Vec3::Zero();
    for (int v : m.faces[f]) c += m.positions[v];
    c /= 3;
    selected[f] = std::abs(c.x() - 8) < 4 && std::abs(c.y() - 8) < 4;
  }
  for (bool flips : {false, true}) {
    m = before;
    FlowOptions opt;
    opt.maxSteps = 3000;
    opt.flipEdges = flips;
    const FlowReport r = fair(m, FaceSet::fromFlags(selected), opt);
    EXPECT_EQ(r.regionFaces, FaceSet::fromFlags(selected).faces);
    EXPECT_LT(r.energyFinal, r.energyInitial);
    int moved = 0;
    for (int v = 0; v < m.vertexCount(); ++v) {
      const Vec3& p = before.positions[v];
      const bool inside = std::abs(p.x() - 8) < 3.5 && std::abs(p.y() - 8) < 3.5;
      if (!inside) EXPECT_EQ(std::memcmp(m.positions[v].data(), p.data(), sizeof(Vec3)), 0) << "vertex " << v;
      moved += m.positions[v] != p;
    }
    EXPECT_GT(moved, 20);
    for (int f = 0; f < m.faceCount(); ++f)
      if (!selected[f]) EXPECT_EQ(m.faces[f], before.faces[f]) << "face " << f;
  }
}

// With a fixed boundary, the boundary row and the next row never move (G¹ clamp).
TEST(Flow, FixedBoundaryClampsTwoRows) {
  TriMesh m = test::jittered(shapes::grid(10, 10, 1.0), 0.2, 6);
  const TriMesh before = m;
  FlowOptions opt;
  opt.maxSteps = 2000;
  fair(m, opt);
  for (int v = 0; v < m.vertexCount(); ++v) {
    const int i = v % 11, j = v / 11;
    if (i <= 1 || j <= 1 || i >= 9 || j >= 9) EXPECT_EQ(m.positions[v], before.positions[v]) << v;
  }
}

// Slide: boundary vertices move, but only along the original boundary lines (here the square's
// sides), towards even spacing.
TEST(Flow, SlidingBoundaryStaysOnTheBoundary) {
  TriMesh m = shapes::grid(8, 8, 1.0);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (Vec3& p : m.positions) {
    const bool onX = p.x() == 0 || p.x() == 8, onY = p.y() == 0 || p.y() == 8;
    if (!onX) p.x() += u(rng);  // boundary points slide along their side only
    if (!onY) p.y() += u(rng);
    if (!onX && !onY) p.z() = u(rng);
  }
  const TriMesh before = m;
  FlowOptions opt;
  opt.boundary = BoundaryMode::Slide;
  opt.maxSteps = 3000;
  const FlowReport r = fair(m, opt);
  EXPECT_LT(r.energyFinal, r.energyInitial);
  int slid = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    const Vec3& p0 = before.positions[v];
    const Vec3& p = m.positions[v];
    const bool onX = p0.x() == 0 || p0.x() == 8, onY = p0.y() == 0 || p0.y() == 8;
    if (onX) EXPECT_NEAR(p.x(), p0.x(), 1e-12);
    if (onY) EXPECT_NEAR(p.y(), p0.y(), 1e-12);
    if (onX || onY) {
      EXPECT_NEAR(p.z(), 0.0, 1e-12);
      slid += (p - p0).norm() > 1e-3;
    }
  }
  EXPECT_GT(slid, 10);
}

// Dynamic connectivity: non-Delaunay edges among moving vertices are flipped; nothing else changes.
TEST(EdgeFlips, MakeTheMovingRegionDelaunay) {
  TriMesh m = shapes::grid(10, 10, 1.0);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-0.45, 0.45);
  for (Vec3& p : m.positions) {
    if (p.x() > 0 && p.x() < 10 && p.y() > 0 && p.y() < 10) p += Vec3(u(rng), u(rng), 0.1 * u(rng));
  }
  const TriMesh before = m;
  const Topology t0(m.vertexCount(), m.faces);
  std::vector<std::uint8_t> movable(m.vertexCount(), 0);
  for (int v = 0; v < m.vertexCount(); ++v) movable[v] = m.positions[v].x() > 2.5 && m.positions[v].x() < 7.5;
  const int flips = flipToDelaunay(m, movable);
  EXPECT_GT(flips, 5);
  EXPECT_EQ(m.positions, before.positions);
  const Topology t(m.vertexCount(), m.faces);
  EXPECT_EQ(t.edgeCount(), t0.edgeCount());
  EXPECT_EQ(t.inconsistentEdgeCount(), 0);
  const Geometry g = computeGeometry(t, m.positions);
  for (int e = 0; e < t.edgeCount(); ++e) {
    const auto& oc = t.edgeOppositeCorners(e);
    if (oc[1] < 0) continue;
    const int vs[4] = {t.edgeVertices(e)[0], t.edgeVertices(e)[1], m.faces[oc[0] / 3][oc[0] % 3], m.faces[oc[1] / 3][oc[1] % 3]};
    bool allMovable = true;
    for (int v : vs) allMovable = allMovable && movable[v];
    if (allMovable) EXPECT_LE(g.cornerAngle(oc[0]) + g.cornerAngle(oc[1]), M_PI + 1e-6) << "edge " << e;
  }
  // Faces with a fixed vertex are untouched.
  for (int f = 0; f < m.faceCount(); ++f) {
    bool fixedVertex = false;
    for (int v : before.faces[f]) fixedVertex = fixedVertex || !movable[v];
    if (fixedVertex) EXPECT_EQ(m.faces[f], before.faces[f]) << f;
  }
}

// Two quads whose far corners coincide (c above and d below a long, narrow rectangle: both long
// sides are non-Delaunay, both would become edge c–d). One pass must not flip both: the second
// flip would give c–d four faces.
TEST(EdgeFlips, NeverCreateAnEdgeTwice) {
  TriMesh m;
  m.positions = {{0, 0, 0.05}, {0, 0, -0.05}, {0.3, -1, 0}, {0.3, 1, 0}, {-0.3, 1, 0}, {-0.3, -1, 0}};
  m.faces = {{2, 3, 0}, {3, 4, 0}, {4, 5, 0}, {5, 2, 0}, {3, 2, 1}, {4, 3, 1}, {5, 4, 1}, {2, 5, 1}};
  const int flips = flipToDelaunay(m, std::vector<std::uint8_t>(6, 1));
  EXPECT_EQ(flips, 1);
  const Topology t(m.vertexCount(), m.faces);  // throws on a non-manifold edge
  EXPECT_EQ(t.edgeCount(), 12);
  EXPECT_EQ(t.boundaryEdgeCount(), 0);
  EXPECT_EQ(t.inconsistentEdgeCount(), 0);
}

TEST(Subdivision, KeepsOldVerticesAndQuadruplesFaces) {
  TriMesh m = test::jittered(shapes::torus(3, 1, 12, 6), 0.1, 9);
  const TriMesh before = m;
  const Topology t(m.vertexCount(), m.faces);
  std::vector<std::uint8_t> flags(m.faceCount());
  for (int f = 0; f < m.faceCount(); ++f) flags[f] = f % 3 == 0;
  subdivideMidpoint(m, &flags);
  EXPECT_EQ(m.faceCount(), 4 * before.faceCount());
  EXPECT_EQ(m.vertexCount(), before.vertexCount() + t.edgeCount());
  for (int v = 0; v < before.vertexCount(); ++v) EXPECT_EQ(m.positions[v], before.positions[v]);
  for (int f = 0; f < m.faceCount(); ++f) EXPECT_EQ(flags[f], (f / 4) % 3 == 0);
  // Every new vertex is the midpoint of an old edge: the surface is unchanged.
  for (int e = 0; e < t.edgeCount(); ++e) {
    const Vec3 mid = 0.5 * (before.positions[t.edgeVertices(e)[0]] + before.positions[t.edgeVertices(e)[1]]);
    bool found = false;
    for (int v = before.vertexCount(); v < m.vertexCount() && !found; ++v) found = m.positions[v] == mid;
    EXPECT_TRUE(found) << "edge " << e;
  }
  const Topology t2(m.vertexCount(), m.faces);
  EXPECT_EQ(t2.eulerCharacteristic(), t.eulerCharacteristic());
}

// The fair() schedule subdivides with no jump in shape: the first stage's end state is kept.
TEST(Flow, SubdivisionStageStartsFromTheCoarseResult) {
  TriMesh m = radialNoise(shapes::icosphere(1.0, 1), 0.05, 5);
  FlowOptions opt;
  opt.subdivisionLevels = 2;
  opt.maxSteps = 200000;
  const FlowReport r = fair(m, opt);
  ASSERT_EQ(r.stages.size(), 3u);
  EXPECT_EQ(r.stages[1].faces, 4 * r.stages[0].faces);
  EXPECT_EQ(r.stages[2].faces, 4 * r.stages[1].faces);
  EXPECT_EQ(m.faceCount(), r.stages[2].faces);
}

TEST(Flow, LimitsCancellationAndErrors) {
  const TriMesh noisy = radialNoise(shapes::icosphere(1.0, 2), 0.05, 7);
  TriMesh m = noisy;
  FlowOptions opt;
  opt.maxSteps = 1234;
  EXPECT_EQ(fair(m, opt).steps, 1234);
  EXPECT_EQ(fair(m, opt).stop, StopReason::MaxSteps);

  m = noisy;
  opt.maxSteps = 1000000;
  opt.progress = [](const FlowProgress& p) { return p.step < 500; };
  const FlowReport cancelled = fair(m, opt);
  EXPECT_EQ(cancelled.stop, StopReason::Cancelled);
  EXPECT_EQ(cancelled.steps, 500);

  // Nothing selected: nothing can move.
  m = noisy;
  EXPECT_THROW(fair(m, FaceSet({}), FlowOptions{}), InvalidInputError);
  EXPECT_EQ(m.positions, noisy.positions);
  // A face index that is not a face of the mesh.
  EXPECT_THROW(fair(m, FaceSet({0, m.faceCount()}), FlowOptions{}), InvalidInputError);
  EXPECT_EQ(m.positions, noisy.positions);

  FlowOptions bad;
  bad.stepFactor = -1;
  EXPECT_THROW(fair(m, bad), InvalidInputError);
}

// The step and time limits hold in both schemes, however far the energy is from a plateau
// (tolerance 0), including the semi-implicit scheme's rejected attempts. The time limit is
// checked with a generous bound: 10× the limit, not a speed measurement.
TEST(Flow, StepAndTimeLimitsHoldInBothSchemes) {
  // 2,562 vertices: the semi-implicit scheme needs seconds to its plateau, the explicit one hours.
  const TriMesh noisy = radialNoise(shapes::icosphere(1.0, 4), 0.05, 11);
  for (Scheme scheme : {Scheme::Explicit, Scheme::SemiImplicit}) {
    FlowOptions opt;
    opt.scheme = scheme;
    opt.energyTolerance = opt.plateauTolerance = 0;
    opt.maxSteps = 7;
    TriMesh m = noisy;
    FlowReport r = fair(m, opt);
    EXPECT_EQ(r.steps, 7);
    EXPECT_EQ(r.stop, StopReason::MaxSteps);

    opt.maxSteps = 1'000'000'000;
    opt.maxSeconds = 0.5;
    opt.subdivisionLevels = 1;
    m = noisy;
    const auto start = std::chrono::steady_clock::now();
    r = fair(m, opt);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.stop, StopReason::MaxSeconds);
    EXPECT_GE(r.seconds, 0.5);
    EXPECT_LT(seconds, 5.0);
  }
}

// A limit reached just as a stage reaches its plateau ends the run there: no subdivision into a
// stage that could not take a step.
TEST(Flow, LimitAtAStageEndDoesNotSubdivide) {
  const TriMesh noisy = radialNoise(shapes::icosphere(1.0, 1), 0.05, 5);
  FlowOptions opt;
  opt.subdivisionLevels = 1;
  TriMesh m = noisy;
  const FlowReport full = fair(m, opt);
  ASSERT_EQ(full.stages.size(), 2u);
  opt.maxSteps = full.stages[0].steps;
  m = noisy;
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::MaxSteps);
  EXPECT_EQ(r.steps, full.stages[0].steps);
  EXPECT_EQ(r.stages.size(), 1u);
  EXPECT_EQ(m.faceCount(), noisy.faceCount());
}

// A step 7,500× the paper's is unstable: the run stops with an error and the mesh is rolled back to
// the last good (finite) state.
TEST(Flow, DivergenceRestoresTheLastGoodState) {
  TriMesh m = radialNoise(shapes::icosphere(1.0, 2), 0.05, 8);
  const Topology topo(m.vertexCount(), m.faces);
  const double edge0 = meanEdgeLength(topo, m.positions);
  FlowOptions opt;
  opt.stepFactor = 50;
  opt.checkInterval = 10;
  EXPECT_THROW(fair(m, opt), NumericalError);
  // The restored state is one that passed the checks: finite, size within a factor 2 per check.
  for (const Vec3& p : m.positions) EXPECT_TRUE(p.allFinite());
  EXPECT_LT(meanEdgeLength(topo, m.positions), 10 * edge0);
}

// The semi-implicit scheme (Scheme::SemiImplicit) passes the explicit scheme's shape tests in a
// few dozen steps instead of tens of thousands.
TEST(SemiImplicit, RoundSphereStaysRound) {
  TriMesh m = shapes::icosphere(1.0, 3);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Converged);
  for (const Vec3& p : m.positions) EXPECT_NEAR(p.norm(), 1.0, 1e-3);
}

// Known gap: the semi-implicit run reaches the explicit run's energy (24.8945 vs 24.8949) in 44
// steps instead of 44,400, but stops with a radius spread of 1.4 % where the explicit run reaches
// 0.39 %. On the 162-vertex sphere alone it ends at a *lower* discrete energy than the explicit run
// (24.19127 vs 24.19144) with spread 1.41 % vs 0.06 %: its large steps find vertex distributions
// that the discretisation rewards. Bounded here as measured; the explicit test holds the 0.5 % bar.
TEST(SemiImplicit, NoisySphereBecomesRound) {
  TriMesh m = radialNoise(shapes::icosphere(1.0, 2), 0.05, 1);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  opt.subdivisionLevels = 1;
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_LT(r.steps, 500);
  EXPECT_EQ(m.vertexCount(), 642);
  EXPECT_LT(radii(m).spread(), 0.02);
  EXPECT_NEAR(energyOf(m), 8 * M_PI, 0.02 * 8 * M_PI);
}

// Torus R/r = 3 to the Clifford torus R/r = √2 (E = 8π²), stopping at the plateau. The discrete
// energy underestimates at O(h²) and the flow's discrete minimum sits below the sampled Clifford
// torus: measured −3.6 % at 48×16 (768 vertices; the sampled Clifford torus of that resolution:
// −2.4 %), −1.7 % at 64×32 (2,048), −1.1 % at 96×32 (3,072; R/r 1.408, about 60 steps). This
// resolution is the coarsest that meets the 2 % (asserted: R/r within 3 % of √2, E within 2 %).
TEST(SemiImplicit, TorusReachesCliffordTorus) {
  TriMesh m = shapes::torus(3, 1, 96, 32);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_LT(r.steps, 1000);
  EXPECT_NEAR(aspectRatio(m), std::sqrt(2.0), 0.03 * std::sqrt(2.0));
  EXPECT_NEAR(energyOf(m), 8 * M_PI * M_PI, 0.02 * 8 * M_PI * M_PI);
  EXPECT_NEAR(r.energyFinal, energyOf(m), 1e-9 * energyOf(m));
}

TEST(SemiImplicit, FixedVerticesAreBitIdentical) {
  TriMesh m = test::jittered(shapes::grid(12, 12, 1.0), 0.2, 6);
  const TriMesh before = m;
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  const FlowReport r = fair(m, opt);
  EXPECT_LT(r.energyFinal, r.energyInitial);
  for (int v = 0; v < m.vertexCount(); ++v) {
    const int i = v % 13, j = v / 13;
    if (i <= 1 || j <= 1 || i >= 11 || j >= 11)
      EXPECT_EQ(std::memcmp(m.positions[v].data(), before.positions[v].data(), sizeof(Vec3)), 0) << v;
  }
}

// The tangential drift after an accepted step obeys the step's rules (no face turned over, E not
// above the step's allowance): on the subdivided tubular cage an unchecked drift pass once folded
// the mesh and lifted E from 523 to 10⁶ in one "accepted" step.
TEST(SemiImplicit, DriftKeepsTheStepRules) {
  TriMesh m = shapes::frameCage(2, 1);
  subdivideMidpoint(m);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  opt.subdivisionLevels = 1;
  opt.maxSteps = 300;
  std::vector<std::pair<int, double>> seen;  // (level, E) after every accepted step
  opt.progress = [&](const FlowProgress& p) {
    seen.emplace_back(p.level, p.energy);
    return true;
  };
  fair(m, opt);
  ASSERT_GT(seen.size(), 20u);
  EXPECT_EQ(seen.back().first, 1);
  for (size_t k = 1; k < seen.size(); ++k) {
    if (seen[k].first != seen[k - 1].first) continue;  // subdivision changes E
    EXPECT_LE(seen[k].second, seen[k - 1].second * (1 + 1e-4) + 1e-9) << "accepted step " << k;
  }
}

TEST(SemiImplicit, BilaplacianIsExplicitOnly) {
  TriMesh m = shapes::icosphere(1.0, 1);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  opt.flow = FlowType::Bilaplacian;
  EXPECT_THROW(fair(m, opt), InvalidInputError);
}
