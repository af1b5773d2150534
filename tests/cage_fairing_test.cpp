// SPDX-License-Identifier: GPL-3.0-or-later
// The flow issue's cage experiment as tests: coarse polygon cages written by hand (data/cages/,
// quads split by the reader along one diagonal, CAD slivers), faired by the default pipeline
// (semi-implicit with remeshing), against what is known of the continuum minimisers. Roundness and
// torus proportions are measured about least-squares fits, not vertex centroids: remeshing spreads
// the vertices unevenly, which moves their centroid but not the surface.
#include "cad_parts.h"
#include "self_intersections.h"
#include "shape_measures.h"

#include <elastica/fairing.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/mesh_curvature.h>
#include <elastica/shapes.h>
#include <elastica/subdivision.h>
#include <elastica/topology.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace elastica;

namespace {

TriMesh cage(const std::string& name) { return io::readMesh(std::string(ELASTICA_DATA_DIR) + "/cages/" + name).mesh; }

int genusOf(const TriMesh& m) {
  const Topology t(m.vertexCount(), m.faces);
  EXPECT_EQ(t.boundaryEdgeCount(), 0);
  return (2 - (m.vertexCount() - t.edgeCount() + m.faceCount())) / 2;
}

// The energy measured afresh from the mesh, with the given vertex areas.
double energyWith(const TriMesh& m, VertexArea area) {
  CurvatureMeasureOptions o;
  o.area = area;
  return measureCurvature(m, o).energy;
}

// R/r of a torus of revolution fitted to the surface: centre and axis from the area-weighted
// centroid and second moments of the faces (independent of how the vertices are spread), then
// R and r minimising Σ (dist(p, tube circle) − r)² over the vertices (Gauss–Newton).
double fittedAspectRatio(const TriMesh& m) {
  Vec3 c = Vec3::Zero();
  double area = 0;
  for (const Face& f : m.faces) {
    const Vec3 &a = m.positions[f[0]], &b = m.positions[f[1]], &d = m.positions[f[2]];
    const double w = 0.5 * (b - a).cross(d - a).norm();
    c += w * (a + b + d) / 3;
    area += w;
  }
  c /= area;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const Face& f : m.faces) {
    const Vec3 &a = m.positions[f[0]], &b = m.positions[f[1]], &d = m.positions[f[2]];
    const Vec3 q = (a + b + d) / 3 - c;
    second += 0.5 * (b - a).cross(d - a).norm() * q * q.transpose();
  }
  const Vec3 axis = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(second).eigenvectors().col(0);
  double R = 0, r = 0;
  for (const Vec3& p : m.positions) {
    const Vec3 q = p - c;
    R += (q - q.dot(axis) * axis).norm() / m.vertexCount();
  }
  for (const Vec3& p : m.positions) {
    const Vec3 q = p - c;
    r += std::hypot((q - q.dot(axis) * axis).norm() - R, q.dot(axis)) / m.vertexCount();
  }
  for (int it = 0; it < 50; ++it) {
    Eigen::Matrix2d JtJ = Eigen::Matrix2d::Zero();
    Eigen::Vector2d Jtr = Eigen::Vector2d::Zero();
    for (const Vec3& p : m.positions) {
      const Vec3 q = p - c;
      const double rho = (q - q.dot(axis) * axis).norm(), h = q.dot(axis);
      const double d = std::hypot(rho - R, h);
      const Eigen::Vector2d J(-(rho - R) / d, -1);
      JtJ += J * J.transpose();
      Jtr += J * (d - r);
    }
    const Eigen::Vector2d step = JtJ.ldlt().solve(-Jtr);
    R += step[0];
    r += step[1];
  }
  return R / r;
}

// A CAD part of genus 1 faired by default within `seconds` (a guard against a hang): it must end a
// true `converged` on the Clifford torus, E within 3 % of 8π², genus kept, no face crossing.
FlowReport expectCliffordTorus(TriMesh& m, double seconds) {
  FlowOptions opt;
  opt.maxSeconds = seconds;
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_EQ(genusOf(m), 1);
  EXPECT_EQ(test::selfIntersections(m), 0);
  EXPECT_NEAR(energyWith(m, VertexArea::Mixed), 8 * M_PI * M_PI, 0.03 * 8 * M_PI * M_PI);
  return r;
}

// expectCliffordTorus, and resolved: Loop-subdivided once, E within 2 % of the mesh's.
void expectResolvedCliffordTorus(TriMesh& m, double seconds) {
  expectCliffordTorus(m, seconds);
  const double energy = energyWith(m, VertexArea::Mixed);
  TriMesh loop = m;
  subdivideLoop(loop);
  EXPECT_LE(energyWith(loop, VertexArea::Mixed), 1.02 * energy);
}

}  // namespace

// A 5×5 quad torus (25 vertices, pentagonal tube, R/r 2.5), default fair --subdivide 3: the
// Clifford torus, R/r = √2 within 2 % and E = 8π² within 3 %, with either vertex area (measured:
// R/r 1.414 and 1.414, E 78.74 and 78.80 against 78.96).
TEST(CageFairing, QuadTorusReachesTheCliffordTorus) {
  for (VertexArea area : {VertexArea::Mixed, VertexArea::Barycentric}) {
    TriMesh m = cage("torus_quad_5x5.off");
    FlowOptions opt;
    opt.area = area;
    opt.subdivisionLevels = 3;
    const FlowReport r = fair(m, opt);
    EXPECT_EQ(r.stop, StopReason::Converged);
    EXPECT_EQ(genusOf(m), 1);
    EXPECT_EQ(test::selfIntersections(m), 0);
    EXPECT_NEAR(fittedAspectRatio(m), std::sqrt(2.0), 0.02 * std::sqrt(2.0));
    EXPECT_NEAR(energyWith(m, area), 8 * M_PI * M_PI, 0.03 * 8 * M_PI * M_PI);
  }
}

// The same cage midpoint-subdivided three times before the run (1,600 vertices, 800 per handle):
// the default runs the vector scheme on it (Scheme::Automatic counts the input's vertices) and
// reaches the Clifford torus with a true "converged" (measured: 50 attempts, E 78.52, R/r 1.410).
// With the neck judged against each stage's start and two remeshed reflows, the vector scheme
// stalled here at E 78.45 after 514 attempts; with the neck judged against every stage's lowest
// κℓ, it "converged" at E 81.9, R/r 1.70, every stage cut to two steps.
TEST(CageFairing, SubdividedQuadTorusReachesTheCliffordTorusWithTheVectorScheme) {
  TriMesh m = cage("torus_quad_5x5.off");
  for (int level = 0; level < 3; ++level) subdivideMidpoint(m);
  FlowOptions opt;
  opt.maxSeconds = 300;  // a guard against a hang; the run takes under a second
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.scheme, Scheme::Vector);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_EQ(genusOf(m), 1);
  EXPECT_EQ(test::selfIntersections(m), 0);
  EXPECT_NEAR(fittedAspectRatio(m), std::sqrt(2.0), 0.02 * std::sqrt(2.0));
  EXPECT_NEAR(energyWith(m, VertexArea::Mixed), 8 * M_PI * M_PI, 0.03 * 8 * M_PI * M_PI);
}

// Genus-2 and genus-3 block cages (quads split along one diagonal): genus kept, no face crossing,
// E below 4·8π + 4π(2g − 2), the bound the minimiser of each genus satisfies (its Willmore energy
// is below 8π): 125.7 for g = 2, 150.8 for g = 3 (measured at --subdivide 2: 112.8 and 142.3; the
// known genus-2 minimiser has about 112.8).
TEST(CageFairing, HigherGenusCagesKeepTheirHandles) {
  for (const auto& [name, genus] : {std::pair<std::string, int>{"genus2_blocks.off", 2}, {"genus3_blocks.off", 3}}) {
    TriMesh m = cage(name);
    ASSERT_EQ(genusOf(m), genus);
    FlowOptions opt;
    opt.subdivisionLevels = 2;
    const FlowReport r = fair(m, opt);
    EXPECT_EQ(r.stop, StopReason::Converged) << name;
    EXPECT_EQ(genusOf(m), genus) << name;
    EXPECT_EQ(test::selfIntersections(m), 0) << name;
    EXPECT_LT(energyWith(m, VertexArea::Mixed), 4 * 8 * M_PI + 4 * M_PI * (2 * genus - 2)) << name;
  }
}

// A thin ring cage (data/cages/thin_ring_24x4.off: R/r 10.6, 96 vertices), default fair
// --subdivide 3 (the test of coarse to fine): the Clifford torus's energy 8π² within 3 %,
// genus kept, no face crossing, a true "converged" (measured: E 78.86, 59 attempts, flowing from
// 1,536 vertices; coarse to fine from 283 vertices it pinched the tube and stalled at E 122).
TEST(CageFairing, ThinRingBecomesTheCliffordTorus) {
  TriMesh m = cage("thin_ring_24x4.off");
  FlowOptions opt;
  opt.subdivisionLevels = 3;
  opt.maxSeconds = 300;  // a guard against a hang; the run takes ~2 s
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_EQ(genusOf(m), 1);
  EXPECT_EQ(test::selfIntersections(m), 0);
  EXPECT_NEAR(energyWith(m, VertexArea::Mixed), 8 * M_PI * M_PI, 0.03 * 8 * M_PI * M_PI);
}

// "Converged" is a promise about the shape: whatever the resolution the schedule flows at, a run
// on the thin ring that says converged ends within 3 % of the Clifford torus's 8π² (a torus's
// energy cannot go below it; above it, the shape was still moving). Runs that cannot keep the
// promise say stalled: measured, --subdivide 0 converged at E 78.1, --subdivide 1 stalled at 63
// (its tube pinched), --subdivide 2 converged at 78.6 (it said "stalled" at E 3,824 with 46
// crossing faces before the working-resolution floor rose to 100 + 1,000 per handle).
TEST(CageFairing, ThinRingSaysConvergedOnlyAtTheMinimum) {
  for (int levels : {0, 1, 2}) {
    TriMesh m = cage("thin_ring_24x4.off");
    FlowOptions opt;
    opt.subdivisionLevels = levels;
    opt.maxSeconds = 300;
    const FlowReport r = fair(m, opt);
    const double e = energyWith(m, VertexArea::Mixed);
    if (r.stop == StopReason::Converged) {
      EXPECT_NEAR(e, 8 * M_PI * M_PI, 0.03 * 8 * M_PI * M_PI) << levels;
    }
    EXPECT_EQ(test::selfIntersections(m), 0) << levels;
  }
}

// A CAD-like rod whose sides are triangles of aspect ratio ~47 and whose caps are fans from one
// rim vertex becomes a round sphere: radius spread below 1 % about the least-squares sphere
// (measured 0.0001 %), E within 2 % of 8π.
TEST(CageFairing, SliverRodBecomesASphere) {
  TriMesh m = cage("cad_rod_slivers.off");
  double worstAspect = 0;
  for (const Face& f : m.faces) {
    double lo = 1e300, hi = 0;
    for (int k = 0; k < 3; ++k) {
      const double l = (m.positions[f[k]] - m.positions[f[(k + 1) % 3]]).norm();
      lo = std::min(lo, l), hi = std::max(hi, l);
    }
    worstAspect = std::max(worstAspect, hi / lo);
  }
  ASSERT_GT(worstAspect, 20);
  FlowOptions opt;
  opt.subdivisionLevels = 3;
  fair(m, opt);
  EXPECT_EQ(test::selfIntersections(m), 0);
  EXPECT_LT(test::fittedRadii(m).spread(), 0.01);
  EXPECT_NEAR(energyWith(m, VertexArea::Mixed), 8 * M_PI, 0.02 * 8 * M_PI);
}

// A CAD-like washer (data/cages/cad_washer_slivers.off: genus 1, 2,400 vertices, triangles of
// aspect up to ~40 meeting at sharp edges) becomes the Clifford torus: a true "converged", E within
// 3 % of 8π², genus kept, no face crossing (measured: E 78.90, Loop-subdivided 79.56). Its isotropic
// remeshing made faces cross and was refused, and the flow then crumpled the washer (stalled at
// E 195,393 on 153,633 vertices); its long edges split first, the remeshing is made. No stage and
// not the output has more vertices than the budget the report states before the first step.
TEST(CageFairing, CadWasherBecomesTheCliffordTorusWithinItsVertexBudget) {
  TriMesh m = cage("cad_washer_slivers.off");
  const FlowReport r = expectCliffordTorus(m, 300);  // the run takes about 25 s
  ASSERT_GT(r.vertexBudget, 0);
  for (const FlowStage& stage : r.stages) EXPECT_LE(stage.vertices, r.vertexBudget);
  EXPECT_LE(m.vertexCount(), r.vertexBudget);
}

// Tori of revolution R/r = 3 at three resolutions reach their plateau in at most 100 steps
// (attempts, rejected ones included) each, not more at finer resolution (measured 85 / 67 / 75),
// at R/r within 2 % of √2.
TEST(CageFairing, TorusStepsDoNotGrowWithResolution) {
  for (const auto& [u, v] : {std::pair<int, int>{48, 16}, {96, 32}, {192, 64}}) {
    TriMesh m = shapes::torus(3, 1, u, v);
    const FlowReport r = fair(m, FlowOptions{});
    EXPECT_EQ(r.stop, StopReason::Converged) << u << "x" << v;
    EXPECT_LE(r.steps, 100) << u << "x" << v;
    EXPECT_NEAR(fittedAspectRatio(m), std::sqrt(2.0), 0.02 * std::sqrt(2.0)) << u << "x" << v;
  }
}

// The pipeline is scale-covariant: every length it compares is relative to the mesh's own edges
// and areas, so the cage at 2¹⁰ times its size comes out 2¹⁰ times larger, with the same
// remeshing and flips (same vertex and face counts) and positions within 1e-9 of the size. (A
// power of two scales every floating-point operation exactly; with 1000 the last bits differ and
// a step or flip decided at its threshold goes the other way.)
TEST(CageFairing, PipelineIsScaleCovariant) {
  constexpr double kScale = 1024;
  const TriMesh small = cage("hex_nut.off");
  TriMesh large = small;
  for (Vec3& p : large.positions) p *= kScale;
  TriMesh a = small, b = large;
  FlowOptions opt;
  opt.subdivisionLevels = 2;
  const FlowReport ra = fair(a, opt), rb = fair(b, opt);
  EXPECT_EQ(ra.steps, rb.steps);
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  ASSERT_EQ(a.faces, b.faces);
  double worst = 0;
  for (int i = 0; i < a.vertexCount(); ++i) worst = std::max(worst, (b.positions[i] / kScale - a.positions[i]).norm());
  EXPECT_LT(worst, 1e-9 * 4);  // the nut is 4 across
}

// A CAD tube whose wall is 1 % of its radius (radii 0.5 and 0.495, length 0.45, 150 segments):
// every remeshing of it but the one on its surface makes faces cross, and on that one (edges six
// times the wall) the flow presses the wall's two sheets together and stalls crumpled, a worse
// surface than the input (Loop-subdivided E 1,364 against the input's 450). The run must not
// claim a result: it says `unchanged` with the reason, and the input comes back, bit for bit,
// without a crossing face (main said `stalled` on it once; on the held-out CAD parts rotor and
// anchor it said `stalled` on remeshings that crossed at 511 and 245 faces).
TEST(CageFairing, ThinWalledCadTubeThatNoStateImprovesComesBackUnchanged) {
  const TriMesh tube = test::cadRing(150, 0.5, 0.495, 0.225);
  ASSERT_EQ(genusOf(tube), 1);
  ASSERT_EQ(test::selfIntersections(tube), 0);
  TriMesh m = tube;
  FlowOptions opt;
  opt.maxSeconds = 600;  // a guard against a hang; the run takes 119 attempts, about 15 s of CPU
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Unchanged);
  EXPECT_FALSE(r.refusedBecause.empty());
  EXPECT_EQ(m.faces, tube.faces);
  EXPECT_EQ(m.positions, tube.positions);
  EXPECT_EQ(test::selfIntersections(m), 0);
  EXPECT_NEAR(r.energyFinal, energyWith(m, VertexArea::Mixed), 1e-9 * r.energyFinal);
}

// A CAD tube whose wall is 2 % of its radius (radii 0.5 and 0.49, length 0.45, 60 segments of
// slivers): its isotropic remeshing steps over the wall, and every remeshing of the CAD path but
// the one on its surface (remeshOnSurface) makes faces cross; on main it flowed from a 98-vertex
// ring and stalled at E 85.85. Remeshed on its surface (every vertex on the input, the rims kept)
// it becomes the Clifford torus: `converged`, E within 3 % of 8π², resolved (Loop-subdivided once,
// within 2 %), genus kept, no face crossing (measured: 35 attempts, E 78.77).
TEST(CageFairing, ThinCadTubeRemeshedOnItsSurfaceBecomesTheCliffordTorus) {
  TriMesh m = test::cadRing(60, 0.5, 0.49, 0.225);
  ASSERT_EQ(genusOf(m), 1);
  expectResolvedCliffordTorus(m, 60);  // the run takes about 2 s
}

// A flat CAD washer 0.04 thick (radii 1 and 0.6, 60 segments): the isotropic remeshing's edge
// (0.17) is 4.3 times its thickness, and at that size it became a ring of 80 vertices that stalled
// at E 53.7 (below 8π²: unresolved). Sized by its thinnest feature it becomes the Clifford torus:
// a true `converged`, E within 3 % of 8π², resolved (Loop-subdivided once, within 2 %), genus
// kept, no face crossing (measured: 46 attempts, E 78.77, Loop-1 79.52).
TEST(CageFairing, FlatCadWasherIsRemeshedAtItsThicknessAndBecomesTheCliffordTorus) {
  TriMesh m = test::cadRing(60, 1, 0.6, 0.02);
  ASSERT_EQ(genusOf(m), 1);
  expectResolvedCliffordTorus(m, 60);  // the run takes about 2 s
}
