// SPDX-License-Identifier: GPL-3.0-or-later
// fair(mesh, region) where MeshLab users fair: a selected part of a scan. Whatever the run does,
// the mesh that comes back is manifold, has no vertices at one point and no crossing face the
// input did not have, keeps every face off the region bit for bit, and the region's energy (its
// faces' vertices, fixed rings included) is not above its start; or it is the input, unchanged,
// with StopReason::Unchanged. Checked here with measures of the tests' own (vcglib's
// self-intersection test, the public operators), not with the core's guard.
#include "sample_meshes.h"
#include "self_intersections.h"

#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/fairing.h>
#include <elastica/geometry.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numeric>
#include <ostream>
#include <random>
#include <string>
#include <vector>

namespace elastica {
namespace {

using test::readSample;

// Portable random numbers (the standard distributions differ between libraries).
struct Rng {
  std::mt19937_64 engine;
  explicit Rng(std::uint64_t seed) : engine(seed) {}
  double uniform() { return (engine() >> 11) * 0x1.0p-53; }
  double normal() { return std::sqrt(-2 * std::log(1 - uniform())) * std::cos(2 * M_PI * uniform()); }
};

double meanEdge(const TriMesh& m) { return meanEdgeLength(Topology(m.vertexCount(), m.faces), m.positions); }

// The faces whose centroid is within the `quantile` of the centroids' distances to `p`.
std::vector<int> regionAround(const TriMesh& m, const Vec3& p, double quantile) {
  std::vector<double> d(m.faces.size());
  for (std::size_t f = 0; f < d.size(); ++f) {
    const Face& t = m.faces[f];
    d[f] = ((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3 - p).norm();
  }
  std::vector<double> sorted = d;
  const std::size_t k = static_cast<std::size_t>(quantile * (sorted.size() - 1));
  std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
  std::vector<int> region;
  for (std::size_t f = 0; f < d.size(); ++f)
    if (d[f] <= sorted[k]) region.push_back(static_cast<int>(f));
  return region;
}

// The issue's recipe: regionAround a random vertex.
std::vector<int> seededRegion(const TriMesh& m, Rng& rng, double quantile) {
  return regionAround(m, m.positions[static_cast<int>(rng.uniform() * m.vertexCount())], quantile);
}

// N(0, sigma) on every coordinate of the region's faces' vertices.
void addNoise(TriMesh& m, const std::vector<int>& region, double sigma, Rng& rng) {
  std::vector<std::uint8_t> done(m.positions.size(), 0);
  for (int f : region)
    for (int v : m.faces[f])
      if (!done[v]++)
        for (int k = 0; k < 3; ++k) m.positions[v][k] += sigma * rng.normal();
}

// `m` with addNoise of a tenth of its mean edge on `region`, drawn from Rng(seed).
TriMesh withNoise(const TriMesh& m, const std::vector<int>& region, std::uint64_t seed) {
  TriMesh noisy = m;
  Rng rng(seed);
  addNoise(noisy, region, 0.1 * meanEdge(m), rng);
  return noisy;
}

// Σ (4H² − 2K) A over the vertices of `faces` (interior regular ones), on the whole mesh.
double regionEnergy(const TriMesh& m, const std::vector<int>& faces) {
  const Topology topo(m.vertexCount(), m.faces);
  const Geometry geo = computeGeometry(topo, m.positions, VertexArea::Mixed);
  const Curvature c = computeCurvature(topo, geo, m.positions, {});
  std::vector<std::uint8_t> mask(m.positions.size(), 0);
  for (int f : faces)
    for (int v : m.faces[f]) mask[v] = 1;
  return totalCurvatureEnergy(topo, geo, c, &mask);
}

using Key = std::array<std::uint64_t, 9>;
// Every face not in `region`, as its corners' bits from the least corner, sorted.
std::vector<Key> facesOff(const TriMesh& m, const std::vector<int>& region) {
  std::vector<std::uint8_t> in(m.faces.size(), 0);
  for (int f : region) in[f] = 1;
  std::vector<Key> keys;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (in[f]) continue;
    std::array<std::array<std::uint64_t, 3>, 3> c;
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) std::memcpy(&c[k][d], &m.positions[m.faces[f][k]][d], 8);
    const int s = static_cast<int>(std::min_element(c.begin(), c.end()) - c.begin());
    Key key;
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) key[3 * k + d] = c[(s + k) % 3][d];
    keys.push_back(key);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

int coincidentVertices(const TriMesh& m) {
  std::vector<std::uint8_t> used(m.positions.size(), 0);
  for (const Face& f : m.faces)
    for (int v : f) used[v] = 1;
  std::vector<std::array<double, 3>> p;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) p.push_back({m.positions[v].x(), m.positions[v].y(), m.positions[v].z()});
  std::sort(p.begin(), p.end());
  return static_cast<int>(std::adjacent_find(p.begin(), p.end()) != p.end());
}

// Runs fair(m, region) and checks every promise of its contract on the result.
FlowReport expectRegionKept(const TriMesh& input, const std::vector<int>& region, const FlowOptions& opt,
                            const std::string& what, TriMesh* output = nullptr) {
  TriMesh local = input;
  TriMesh& m = output ? *output : local;
  m = input;
  const FlowReport r = fair(m, FaceSet(region), opt);
  SCOPED_TRACE(what + ": stop " + std::to_string(static_cast<int>(r.stop)) + " " + r.refusedBecause);
  const Topology topo(m.vertexCount(), m.faces);  // throws on a non-manifold edge
  EXPECT_EQ(topo.nonManifoldVertexCount(), 0);
  EXPECT_EQ(topo.inconsistentEdgeCount(), 0);
  EXPECT_EQ(coincidentVertices(m), 0);
  EXPECT_LE(test::selfIntersections(m), test::selfIntersections(input));
  EXPECT_EQ(facesOff(m, r.regionFaces), facesOff(input, region));
  const double before = regionEnergy(input, region), after = regionEnergy(m, r.regionFaces);
  EXPECT_LE(after, before);
  EXPECT_NEAR(r.regionEnergyBefore, before, 1e-9 * std::abs(before));
  EXPECT_NEAR(r.regionEnergyAfter, after, 1e-9 * std::abs(before));
  if (r.stop == StopReason::Unchanged) {  // nothing passed: the input, bit for bit
    EXPECT_FALSE(r.refusedBecause.empty());
    EXPECT_EQ(r.keptStage, -1);
    EXPECT_EQ(m.positions, input.positions);
    EXPECT_EQ(m.faces, input.faces);
  } else if (!r.refusedBecause.empty()) {  // the last state failed: an earlier stage's end came back
    EXPECT_GE(r.keptStage, 0);
    EXPECT_LT(r.keptStage, static_cast<int>(r.stages.size()));
  }
  return r;
}

// The faces of `m` whose centroid lies above height `z`.
std::vector<int> facesAbove(const TriMesh& m, double z) {
  std::vector<int> faces;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const Face& t = m.faces[f];
    if ((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]).z() / 3 > z) faces.push_back(f);
  }
  return faces;
}

// The largest distance of a vertex of `faces` from the sphere of radius `r` about the origin.
double worstDistanceToSphere(const TriMesh& m, const std::vector<int>& faces, double r) {
  double worst = 0;
  for (int f : faces)
    for (int v : m.faces[f]) worst = std::max(worst, std::abs(m.positions[v].norm() - r));
  return worst;
}

// A spherical cap region, its interior jittered: the clamped rings hold position and tangent plane
// of the sphere, whose cap is the elastica with that boundary (a Willmore surface, E of a cap at
// its minimum), so the flow must bring the cap back onto the sphere.
TEST(RegionFairing, NoisySphereCapReturnsToTheSphere) {
  const double r = 1;
  const TriMesh sphere = shapes::icosphere(r, 4);
  const std::vector<int> cap = facesAbove(sphere, 0.5);
  TriMesh noisy = sphere;
  Rng rng(42);
  std::vector<std::uint8_t> inCap(noisy.positions.size(), 1);
  for (std::size_t f = 0; f < noisy.faces.size(); ++f)
    if (!std::binary_search(cap.begin(), cap.end(), static_cast<int>(f)))
      for (int v : noisy.faces[f]) inCap[v] = 0;
  const double sigma = 0.1 * meanEdge(sphere);
  for (std::size_t v = 0; v < noisy.positions.size(); ++v)
    if (inCap[v]) noisy.positions[v] += sigma * Vec3(rng.normal(), rng.normal(), rng.normal());
  TriMesh m;
  const FlowReport rep = expectRegionKept(noisy, cap, {}, "sphere cap", &m);
  EXPECT_EQ(rep.stop, StopReason::Converged);
  const double worst = worstDistanceToSphere(m, rep.regionFaces, r);
  // Measured 4.1e-5 (the noise's sigma 7.5e-3): the flow took off 99.5 % of it.
  std::printf("cap: worst distance to the sphere %.3g (noise sigma %.3g)\n", worst, sigma);
  EXPECT_LT(worst, 0.02 * sigma);
}

// A hemisphere pressed flat, its vertices drawn in towards the pole (a scan's clusters of small
// triangles), with its triangulation kept (no remeshing, as where a region's remeshing is undone):
// the pole goes back up about 10 mean edge lengths, and the step's motion there is smooth over
// triangles down to a hundredth of the mean edge. Each vertex's jump limit (2 of its own ring's edges) held every step
// to the smallest triangles; the limit that asks whether the step strains the mesh
// (VectorIntegrator::strainJumpLimit) lets it go. Measured: converged round in 44 attempts; 717
// without the strain limit.
TEST(RegionFairing, PressedHemisphereOfSmallTrianglesComesBackRound) {
  const double r = 1;
  const TriMesh sphere = shapes::icosphere(r, 4);
  const std::vector<int> cap = facesAbove(sphere, 0);
  const double ell = meanEdge(sphere);
  const double plane = 2.5 * ell;  // above the two fixed rings at the equator
  const double rim = std::sqrt(r * r - plane * plane);
  TriMesh pressed = sphere;
  for (Vec3& p : pressed.positions) {
    if (p.z() <= plane) continue;
    const double rho = std::hypot(p.x(), p.y()) / rim;  // ρ → ρ³: small triangles round the pole
    p.x() *= rho * rho, p.y() *= rho * rho;
    p.z() = plane + 0.05 * (p.z() - plane);
  }
  FlowOptions opt;
  opt.remesh = false;
  opt.maxSteps = 100;
  TriMesh m;
  const FlowReport rep = expectRegionKept(pressed, cap, opt, "pressed hemisphere", &m);
  EXPECT_EQ(rep.stop, StopReason::Converged);
  // Measured 1.4e-6 (ℓ = 0.075); 0.71 without the strain limit, at the 100-step budget.
  EXPECT_LT(worstDistanceToSphere(m, rep.regionFaces, r), 1e-3 * ell);
}

// A noisy cap of about 1,000 faces on an icosphere of 40,962 vertices: the run works on a piece
// around the cap (flow/region_fairing.cpp) and splices its result back. The promises are the
// same as on a small mesh, and the rest of the mesh keeps its order: the faces off the region come
// back in their order, and if the region did not shrink, every vertex off its interior keeps its
// index and its bits.
TEST(RegionFairing, RegionOfABigMeshKeepsTheRest) {
  const TriMesh sphere = shapes::icosphere(1, 6);
  ASSERT_GE(sphere.vertexCount(), 40000);
  std::vector<int> cap;
  for (std::size_t f = 0; f < sphere.faces.size(); ++f) {
    const Face& t = sphere.faces[f];
    if ((sphere.positions[t[0]] + sphere.positions[t[1]] + sphere.positions[t[2]]).normalized().z() > 0.975)
      cap.push_back(static_cast<int>(f));
  }
  ASSERT_GT(cap.size(), 800u);
  ASSERT_LT(cap.size(), 1300u);
  const TriMesh noisy = withNoise(sphere, cap, 5);
  FlowOptions opt;
  opt.maxSteps = 300;
  // The run and its checks build no topology of the whole mesh (the piece has a few thousand vertices).
  TriMesh m = noisy;
  Topology::resetLargestBuilt();
  fair(m, FaceSet(cap), opt);
  EXPECT_LT(Topology::largestBuilt(), noisy.vertexCount() / 4);
  const FlowReport r = expectRegionKept(noisy, cap, opt, "icosphere cap", &m);
  EXPECT_NE(r.stop, StopReason::Unchanged) << r.refusedBecause;
  EXPECT_LT(r.regionEnergyAfter, 0.5 * r.regionEnergyBefore);
  // The faces off the region, in their order, as their corners' positions.
  auto offInOrder = [](const TriMesh& mesh, const std::vector<int>& region) {
    std::vector<std::uint8_t> in(mesh.faces.size(), 0);
    for (int f : region) in[f] = 1;
    std::vector<std::array<Vec3, 3>> faces;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
      if (!in[f]) faces.push_back({mesh.positions[mesh.faces[f][0]], mesh.positions[mesh.faces[f][1]], mesh.positions[mesh.faces[f][2]]});
    return faces;
  };
  EXPECT_TRUE(offInOrder(m, r.regionFaces) == offInOrder(noisy, cap));
  if (m.vertexCount() >= noisy.vertexCount() && m.faceCount() >= noisy.faceCount()) {
    std::vector<std::uint8_t> interior(noisy.positions.size(), 1), inCap(noisy.faces.size(), 0);
    for (int f : cap) inCap[f] = 1;
    for (std::size_t f = 0; f < noisy.faces.size(); ++f)
      if (!inCap[f])
        for (int v : noisy.faces[f]) interior[v] = 0;
    int moved = 0;
    for (std::size_t v = 0; v < interior.size(); ++v)
      if (!interior[v]) moved += std::memcmp(&m.positions[v], &noisy.positions[v], sizeof(Vec3)) != 0;
    EXPECT_EQ(moved, 0);
    for (std::size_t f = 0; f < noisy.faces.size(); ++f) {
      if (!inCap[f]) {
        EXPECT_EQ(m.faces[f], noisy.faces[f]) << "face " << f;
      }
    }
  }
}

struct ScanRegions {
  const char* mesh;
  int regions;
};

class ScanRegionFairing : public ::testing::TestWithParam<ScanRegions> {};

// The issue's recipe on two libcgal-demo scans (the lion's head, open, and the devil mannequin),
// seeded regions of 3 % of the faces, as they are and with N(0, 0.1 mean edge) on their vertices.
// A step budget (not a time limit) keeps the runs short and the same on every machine.
TEST_P(ScanRegionFairing, SeededRegionsNeverBreakTheMesh) {
  const TriMesh scan = readSample(GetParam().mesh);
  const double edge = meanEdge(scan);
  Rng rng(7);
  FlowOptions opt;
  opt.maxSteps = 60;
  for (int i = 0; i < GetParam().regions; ++i) {
    const std::vector<int> region = seededRegion(scan, rng, 0.03);
    expectRegionKept(scan, region, opt, std::string(GetParam().mesh) + " region " + std::to_string(i));
    TriMesh noisy = scan;
    addNoise(noisy, region, 0.1 * edge, rng);
    expectRegionKept(noisy, region, opt, std::string(GetParam().mesh) + " noisy region " + std::to_string(i));
  }
}

// A region that reaches the scan's open border (around its first border vertex), noisy: the
// border row and the next stay fixed, and the promises hold there too.
TEST_P(ScanRegionFairing, RegionAtTheOpenBorder) {
  const TriMesh scan = readSample(GetParam().mesh);
  const Topology topo(scan.vertexCount(), scan.faces);
  int border = -1;
  for (int v = 0; v < scan.vertexCount() && border < 0; ++v)
    if (topo.isBoundaryVertex(v)) border = v;
  ASSERT_GE(border, 0) << "both scans are open";
  const std::vector<int> region = regionAround(scan, scan.positions[border], 0.03);
  const TriMesh noisy = withNoise(scan, region, 11);
  FlowOptions opt;
  opt.maxSteps = 200;
  expectRegionKept(noisy, region, opt, std::string(GetParam().mesh) + " border region");
}

// The region around one of every 97 vertices (the 1 % of faces nearest it) whose faces most often
// face away from the region's mean normal: a thin part (the lion's ear, the devil's horn or
// finger), where the selection wraps round both sides.
std::vector<int> thinPartRegion(const TriMesh& m, int& facingAway) {
  std::vector<Vec3> normal(m.faces.size());
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const Face& t = m.faces[f];
    normal[f] = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).normalized();
  }
  std::vector<int> best;
  facingAway = -1;
  for (int v = 0; v < m.vertexCount(); v += 97) {
    const std::vector<int> region = regionAround(m, m.positions[v], 0.01);
    Vec3 mean = Vec3::Zero();
    for (int f : region) mean += normal[f];
    int away = 0;
    for (int f : region) away += normal[f].dot(mean.normalized()) < -0.3;
    if (away > facingAway) facingAway = away, best = region;
  }
  return best;
}

// A region that runs through a thin part, noisy: both sides of the part move, and the flow must
// neither push one side through the other nor leave the part broken; as a fairing amount and to
// the limit shape.
TEST_P(ScanRegionFairing, RegionThroughAThinPart) {
  const TriMesh scan = readSample(GetParam().mesh);
  int facingAway = 0;
  const std::vector<int> region = thinPartRegion(scan, facingAway);
  EXPECT_GE(facingAway, static_cast<int>(region.size()) / 10) << "the region wraps round a thin part";
  const TriMesh noisy = withNoise(scan, region, 13);
  FlowOptions limit;
  limit.maxSteps = 200;
  expectRegionKept(noisy, region, limit, std::string(GetParam().mesh) + " thin part");
  FlowOptions amount;
  amount.featureSize = 2 * meanEdge(scan);
  const FlowReport r = expectRegionKept(noisy, region, amount, std::string(GetParam().mesh) + " thin part, amount");
  EXPECT_TRUE(r.stop == StopReason::FeatureSize || r.stop == StopReason::Unchanged);
}

// The `faces` faces of a sample scan nearest its vertex `vertex`, faired to the limit shape within
// `maxSteps` steps, its contract checked (expectRegionKept).
FlowReport fairScanRegion(const char* mesh, int vertex, int faces, long long maxSteps, const std::string& what,
                          Scheme scheme = Scheme::Automatic, TriMesh* output = nullptr) {
  const TriMesh scan = readSample(mesh);
  EXPECT_GT(scan.vertexCount(), vertex);
  const std::vector<int> region = regionAround(scan, scan.positions[vertex], static_cast<double>(faces) / scan.faceCount());
  FlowOptions opt;
  opt.maxSteps = maxSteps;
  opt.scheme = scheme;
  return expectRegionKept(scan, region, opt, what, output);
}

// A large region (10,000 of the devil mannequin's 25,888 faces, around the vertex that
// bench/region_sweep.py --sizes draws) that holds many of the scan's own crossing faces: its first
// isotropic remeshing folded faces flat (a corner of 1e-12°), after which the flow's matrices were
// not positive definite and every attempt of both schemes was refused. The remeshing is undone
// (mesh_quality_stage.cpp), and the region flows on its piece: it takes steps and comes back fairer,
// never unchanged.
TEST(ScanRegionFairingLarge, RegionThroughTheScansOwnCrossingsFlows) {
  const FlowReport r = fairScanRegion("mannequin-devil.off", 12262, 10000, 60, "mannequin-devil, 10,000 faces");
  EXPECT_NE(r.stop, StopReason::Unchanged) << r.refusedBecause;
  EXPECT_GT(r.steps - r.rejectedSteps, 0);
  EXPECT_LT(r.regionEnergyAfter, 0.5 * r.regionEnergyBefore);
}

// The issue's recipe's region around `vertex` of the lion's head (3 % of its faces, no noise),
// faired to the limit shape within 600 steps, its contract checked (expectRegionKept).
FlowReport fairRecipeRegion(const char* mesh, int vertex, const std::string& what, Scheme scheme = Scheme::Automatic) {
  const TriMesh scan = readSample(mesh);
  EXPECT_GT(scan.vertexCount(), vertex);
  const std::vector<int> region = regionAround(scan, scan.positions[vertex], 0.03);
  FlowOptions opt;
  opt.maxSteps = 600;
  opt.scheme = scheme;
  return expectRegionKept(scan, region, opt, what);
}

FlowReport fairLionRecipeRegion(int vertex, const std::string& what, Scheme scheme = Scheme::Automatic) {
  return fairRecipeRegion("lion-head.off", vertex, what, scheme);
}

// The issue's recipe's region 1 on the devil mannequin (777 faces around vertex 8,111, no noise):
// its stages' tails at τ far beyond the shape's time lowered W by fractions of a percent an attempt
// until the stop rule read them as settled, and main said converged at region E 49.73 (243
// attempts), which a second run took to 29.62. With preconditioned L-BFGS past the shape's time
// (VectorIntegrator::quasiNewton) the first run ends at 32.05 (322 attempts). (The vector scheme's
// state there is a faceted lid, which fair() with the default scheme does not return:
// ARegionIsNotLeftAFacetedLid below; this test is the scheme's own.)
TEST(ScanRegionFairingSteps, TheTailPastTheShapeTimeIsAccelerated) {
  const FlowReport r = fairRecipeRegion("mannequin-devil.off", 8111, "mannequin-devil region 1", Scheme::Vector);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_LT(r.regionEnergyAfter, 40);
}

// The issue's recipe's region 6 on the lion's head (501 faces around vertex 5,375, as
// bench/region_sweep.py draws it): the same few vertices (valence 3 and 4, left by the edge flips)
// raised W at every first try, the held retries kept τ near a hundredth of the shape's time, and
// the run went on for thousands of attempts (4,415 in 10 s). With the overshooting vertices damped
// (VectorIntegrator::dampOvershoots) it converges in a few dozen, lower.
TEST(ScanRegionFairingSteps, OvershootingVerticesDoNotStallARegion) {
  const FlowReport r = fairLionRecipeRegion(5375, "lion-head region 6");
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_LT(r.steps, 200);
  EXPECT_LT(r.regionEnergyAfter, 0.5 * r.regionEnergyBefore);
}

// The issue's recipe's region 0 on the lion's head (501 faces around vertex 7,895, as
// bench/region_sweep.py draws it): the last of its three stages, after a reflow's curvature-adaptive
// remeshing, ended at E 32.65 (the flow's measure) where the second had ended at 22.2, and the run
// said converged on the last (region E 106.5 → 36.62). A selection's output is its lowest stage end
// at its level (fairRegion's keepEachStage): 22.2, region E 26.17. (The vector scheme's rule.)
TEST(ScanRegionFairingSteps, ASelectionEndsAtItsLowestStage) {
  const FlowReport r = fairLionRecipeRegion(7895, "lion-head region 0", Scheme::Vector);
  ASSERT_FALSE(r.stages.empty());
  double lowest = std::numeric_limits<double>::infinity();
  for (const FlowStage& s : r.stages)
    if (s.level == r.stages.back().level) lowest = std::min(lowest, s.energy);
  EXPECT_LE(r.energyFinal, lowest * (1 + 1e-12));
}

// The 1,000 faces of the lion's head nearest vertex 7,895 (bench/region_sweep.py --sizes 1000): its
// first stage ended at its lowest state, a reflow's remeshing was refused, and the second stage,
// from that state, ended there again; a second reflow's remeshing was refused too, and a third
// stage flowed the second again from the same region, 41 attempts to the same energy, before the
// schedule stopped. A reflow that would start where the last stage started is not flowed
// (fairRegion's repeatsLastStage): no stage is the last one again.
TEST(ScanRegionFairingSteps, NoStageRepeatsTheLast) {
  const FlowReport r = fairScanRegion("lion-head.off", 7895, 1000, 600, "lion-head, 1,000 faces", Scheme::Vector);
  EXPECT_EQ(r.stop, StopReason::Converged);
  for (std::size_t s = 1; s < r.stages.size(); ++s) {
    const FlowStage &a = r.stages[s - 1], &b = r.stages[s];
    EXPECT_FALSE(a.level == b.level && a.steps == b.steps && a.energy == b.energy && a.vertices == b.vertices &&
                 a.faces == b.faces)
        << "stage " << s << " repeats stage " << s - 1 << " (" << b.steps << " attempts, E " << b.energy << ")";
  }
}

// The same region (lion-head's 1,000 faces nearest vertex 7,895): a reflow's remeshing is tried on
// a stage's end state, and on main before this rule the second reflow remeshed the very state on
// which the first reflow's remeshing was refused (the stage between them ended where it started).
// A remeshing is a function of the region and its level, so it is not tried again (fairRegion's
// RefusedRemeshing): no more refusals than distinct stage ends (main: one refusal and one end
// state, where the run tried two; with VectorIntegrator::quasiNewton the second stage goes lower,
// and two states were each refused once).
TEST(ScanRegionFairingSteps, ARefusedRemeshingIsNotTriedAgainOnTheSameState) {
  const FlowReport r = fairScanRegion("lion-head.off", 7895, 1000, 600, "lion-head, 1,000 faces", Scheme::Vector);
  EXPECT_EQ(r.stop, StopReason::Converged);
  std::vector<double> ends;
  for (const FlowStage& stage : r.stages)
    if (std::find(ends.begin(), ends.end(), stage.energy) == ends.end()) ends.push_back(stage.energy);
  EXPECT_GE(r.remeshingsRefused, 1);
  EXPECT_LE(r.remeshingsRefused, static_cast<int>(ends.size()));
}

// A face's area.
double faceArea(const TriMesh& m, const Face& f) {
  return 0.5 * (m.positions[f[1]] - m.positions[f[0]]).cross(m.positions[f[2]] - m.positions[f[0]]).norm();
}

// The same region (lion-head's 1,000 faces nearest vertex 7,895), with the default scheme. The
// vector scheme lowers the discrete energy there by moving the region's vertices out of its
// middle: it ended "converged" at region E 14.4 on a lid of flat faces up to 60 times the scan's
// mean face, whose moving vertices' energy rose from 3.0 to 50 once the region was
// Loop-subdivided (bench/region_sweep.py, docs/decisions.md "Regions"). fair() measures
// that (flow/region_resolution.h) and runs the semi-implicit scheme too: what comes back is
// resolved, and its faces are the scan's size.
TEST(ScanRegionFairingSteps, ARegionIsNotLeftAFacetedLid) {
  const TriMesh scan = readSample("lion-head.off");
  TriMesh out;
  const FlowReport r = fairScanRegion("lion-head.off", 7895, 1000, 2000, "lion-head, 1,000 faces", Scheme::Automatic, &out);
  ASSERT_EQ(r.stop, StopReason::Converged);
  EXPECT_LE(r.regionResolutionGap, 0.1);
  double inputMean = 0;
  for (const Face& f : scan.faces) inputMean += faceArea(scan, f) / scan.faceCount();
  double largest = 0;
  for (int f : r.regionFaces) largest = std::max(largest, faceArea(out, out.faces[f]));
  EXPECT_LT(largest, 4 * inputMean) << "a region face of " << largest / inputMean << " mean faces of the scan";
}

// The same region with no step limit: the vector scheme's first attempts (fairResolved's probe)
// already leave a lid, so the semi-implicit scheme runs first and its converged, resolved result
// comes back without the whole vector run: fewer attempts in all than the vector scheme alone
// takes (lion-head: 150 against 219; fairing the whole vector run first, then the semi-implicit
// one, took 349).
TEST(ScanRegionFairingSteps, ALidSeenInTheFirstAttemptsSkipsTheWholeVectorRun) {
  const long long noLimit = std::numeric_limits<long long>::max();
  const FlowReport vector = fairScanRegion("lion-head.off", 7895, 1000, noLimit, "lion-head, vector", Scheme::Vector);
  const FlowReport r = fairScanRegion("lion-head.off", 7895, 1000, noLimit, "lion-head, 1,000 faces");
  ASSERT_EQ(r.stop, StopReason::Converged);
  EXPECT_LE(r.regionResolutionGap, 0.1);
  EXPECT_EQ(r.scheme, Scheme::SemiImplicit);
  EXPECT_EQ(r.regionRuns, 2);
  EXPECT_LT(r.steps, vector.steps);
}

// N(0, 1) from a hash of (vertex, coordinate) (splitmix64, Box–Muller): the same noise on a vertex
// whatever the region, so that a script can make the same input (the tests' Rng draws in order).
double hashNormal(std::uint64_t vertex, int coordinate) {
  auto mix = [](std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
  };
  const double a = ((mix(6 * vertex + 2 * coordinate) >> 11) + 1) * 0x1.0p-53;  // (0, 1]
  const double b = (mix(6 * vertex + 2 * coordinate + 1) >> 11) * 0x1.0p-53;
  return std::sqrt(-2 * std::log(a)) * std::cos(2 * M_PI * b);
}

// The issue's seeded noisy region (issue 53): the 1,050 faces of `mesh` whose centroids are nearest
// vertex `vertex`, N(0, 0.1 mean edge) on their vertices (hashNormal), faired to the limit shape
// with the default scheme within `maxSteps` attempts (above the 2,080 at which fairResolved probes
// for a lid), its contract checked (expectRegionKept).
FlowReport fairNoisySeededRegion(const char* mesh, int vertex, long long maxSteps) {
  TriMesh scan = readSample(mesh);
  EXPECT_GT(scan.vertexCount(), vertex);
  std::vector<double> d(scan.faces.size());
  for (std::size_t f = 0; f < d.size(); ++f) {
    const Face& t = scan.faces[f];
    d[f] = ((scan.positions[t[0]] + scan.positions[t[1]] + scan.positions[t[2]]) / 3 - scan.positions[vertex]).norm();
  }
  std::vector<int> region(scan.faces.size());
  std::iota(region.begin(), region.end(), 0);
  std::stable_sort(region.begin(), region.end(), [&](int a, int b) { return d[a] < d[b]; });
  region.resize(1050);
  std::sort(region.begin(), region.end());
  const double sigma = 0.1 * meanEdge(scan);
  std::vector<std::uint8_t> done(scan.positions.size(), 0);
  for (int f : region)
    for (int v : scan.faces[f])
      if (!done[v]++)
        for (int k = 0; k < 3; ++k) scan.positions[v][k] += sigma * hashNormal(v, k);
  FlowOptions opt;
  opt.maxSteps = maxSteps;
  return expectRegionKept(scan, region, opt, std::string(mesh) + " seeded region at vertex " + std::to_string(vertex));
}

// Seeded noisy regions that main (b9b8d6f) returned `stalled`: the vector scheme's result, a lid
// (Loop gap +77 % on lion-head, +41 % on mannequin-devil), came back because its Loop-subdivided
// energy was below the semi-implicit scheme's converged, resolved result. A final result now comes
// back over one that is not: converged (or self_contact), the gap within kRegionResolvedGap, within
// twice the attempts measured (lion-head 180, mannequin-devil 151, the same as main's runs).
struct SeededRegion {
  const char* mesh;
  int vertex;
  long long attempts;  // the measured attempts, times two
};
void PrintTo(const SeededRegion& s, std::ostream* os) { *os << s.mesh << " vertex " << s.vertex; }
class SeededNoisyRegion : public ::testing::TestWithParam<SeededRegion> {};
TEST_P(SeededNoisyRegion, ConvergesResolved) {
  const SeededRegion& s = GetParam();
  const FlowReport r = fairNoisySeededRegion(s.mesh, s.vertex, 2500);
  EXPECT_TRUE(r.stop == StopReason::Converged || r.stop == StopReason::SelfContact)
      << "stop " << static_cast<int>(r.stop) << ", gap " << r.regionResolutionGap << ", " << r.steps << " attempts";
  EXPECT_LE(r.regionResolutionGap, kRegionResolvedGap);
  EXPECT_LE(r.steps, s.attempts);
  EXPECT_LT(r.regionEnergyAfter, 0.25 * r.regionEnergyBefore);
  std::printf("%s vertex %d: %lld attempts, gap %+.3f, region E %.4g -> %.4g\n", s.mesh, s.vertex, r.steps,
              r.regionResolutionGap, r.regionEnergyBefore, r.regionEnergyAfter);
}
INSTANTIATE_TEST_SUITE_P(Issue53, SeededNoisyRegion,
                         ::testing::Values(SeededRegion{"lion-head.off", 5223, 360},
                                           SeededRegion{"mannequin-devil.off", 5000, 302}),
                         [](const ::testing::TestParamInfo<SeededRegion>& info) {
                           std::string s = info.param.mesh;
                           s = s.substr(0, s.find('.'));
                           std::replace(s.begin(), s.end(), '-', '_');
                           return s + "_" + std::to_string(info.param.vertex);
                         });

INSTANTIATE_TEST_SUITE_P(LibcgalDemo, ScanRegionFairing,
                         ::testing::Values(ScanRegions{"lion-head.off", 8}, ScanRegions{"mannequin-devil.off", 8}),
                         [](const ::testing::TestParamInfo<ScanRegions>& info) {
                           std::string s = info.param.mesh;
                           s = s.substr(0, s.find('.'));
                           std::replace(s.begin(), s.end(), '-', '_');
                           return s;
                         });

}  // namespace
}  // namespace elastica
