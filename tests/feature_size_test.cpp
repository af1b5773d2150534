// SPDX-License-Identifier: GPL-3.0-or-later
// FlowOptions::featureSize, the fairing amount: the flow's principal part runs for
// t = 2 (size / 2π)⁴ and stops with StopReason::FeatureSize. Checked on a sphere carrying small
// bumps (1 % of the bounding-box diagonal across) and one broad feature (20 % across): the amount
// 3 % removes the bumps and leaves the broad feature where it was; and on a sphere with 3-D vertex
// noise: the noise goes, the radius stays.
#include "test_meshes.h"

#include <elastica/fairing.h>
#include <elastica/mesh_curvature.h>
#include <elastica/shapes.h>
#include <elastica/subdivision.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace elastica;

namespace {

// Radial bump of height h and footprint radius w (a cos² profile) at unit direction c, as a
// function of the point's unit direction u (chord distance).
double bump(const Vec3& u, const Vec3& c, double w, double h) {
  const double d = (u - c).norm();
  if (d >= w) return 0;
  const double s = std::cos(0.5 * M_PI * d / w);
  return h * s * s;
}

struct BumpySphere {
  TriMesh mesh;
  std::vector<Vec3> bumpCentres;
  Vec3 featureCentre;
  double w = 0, featureW = 0;
};

// A unit sphere (level-5 icosphere, ℓ ≈ 0.038) refined twice around its north pole (ℓ ≈ 0.0094,
// so a bump 1 % of the diagonal across spans ~4 edges), with seven bumps there and one broad
// feature on the south side. Bounding-box diagonal ≈ 2√3.
BumpySphere bumpySphere() {
  BumpySphere b;
  b.mesh = shapes::icosphere(1, 5);
  const double diagonal = 2 * std::sqrt(3.0);
  b.w = 0.005 * diagonal;        // footprint radius: 1 % of the diagonal across
  b.featureW = 0.1 * diagonal;   // 20 % across
  const Vec3 pole(0, 0, 1);
  for (int level = 0; level < 2; ++level) {
    std::vector<std::uint8_t> cap(b.mesh.faces.size(), 0);
    for (std::size_t f = 0; f < cap.size(); ++f)
      cap[f] = (b.mesh.positions[b.mesh.faces[f][0]].normalized() - pole).norm() < 0.3;
    subdivideMidpointRegion(b.mesh, cap);
  }
  for (Vec3& p : b.mesh.positions) p.normalize();
  b.bumpCentres.push_back(pole);
  for (int k = 0; k < 6; ++k) {
    const double a = k * M_PI / 3;
    b.bumpCentres.push_back(Vec3(0.09 * std::cos(a), 0.09 * std::sin(a), 1).normalized());
  }
  b.featureCentre = Vec3(1, 0, -1).normalized();
  for (Vec3& p : b.mesh.positions) {
    const Vec3 u = p;
    double r = 1 + bump(u, b.featureCentre, b.featureW, 0.15);
    for (const Vec3& c : b.bumpCentres) r += bump(u, c, b.w, 0.5 * b.w);
    p = r * u;
  }
  return b;
}

// RMS of H − 1 (a unit sphere's H) over the vertices within `radius` of the pole.
double capCurvatureSpread(const TriMesh& m, double radius) {
  const MeshCurvature c = measureCurvature(m);
  double sum = 0;
  int n = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    if ((m.positions[v].normalized() - Vec3(0, 0, 1)).norm() >= radius) continue;
    sum += (c.H[v] - 1) * (c.H[v] - 1);
    ++n;
  }
  return std::sqrt(sum / n);
}

}  // namespace

TEST(FeatureSize, RemovesSmallerBumpsAndKeepsLargerShapes) {
  const BumpySphere b = bumpySphere();
  const double diagonal = boundingBoxDiagonal(b.mesh.positions);
  TriMesh m = b.mesh;
  FlowOptions o;
  o.featureSize = 0.03 * diagonal;
  const FlowReport r = fair(m, o);
  EXPECT_EQ(r.stop, StopReason::FeatureSize);
  ASSERT_EQ(m.vertexCount(), b.mesh.vertexCount());  // no remeshing: vertices correspond

  const double before = capCurvatureSpread(b.mesh, 0.2), after = capCurvatureSpread(m, 0.2);
  EXPECT_LE(after, before / 10) << "H spread over the bumps " << before << " -> " << after;

  double moved = 0;
  for (int v = 0; v < m.vertexCount(); ++v)
    if ((b.mesh.positions[v].normalized() - b.featureCentre).norm() < b.featureW)
      moved = std::max(moved, (m.positions[v] - b.mesh.positions[v]).norm());
  EXPECT_LE(moved, 0.01 * diagonal) << "the broad feature moved by " << moved / diagonal << " of the diagonal";
}

// The amount as a denoiser, on the one surface where the answer is known: a unit sphere (2,562
// vertices, mean edge ℓ ≈ 0.07) whose vertices were moved in 3-D by up to 0.2 ℓ. F = 5ℓ cuts the
// modes of wavelength below F: on a unit sphere about (2π/F)² of the 2,562 modes lie above it, 6 %,
// so the radial noise's RMS should fall to about a quarter (asserted: below 40 %). The sphere
// itself shrinks by 4 (F/2π)⁴ ≈ 2e-4 over that time (flow.h), and the tangential noise raises the
// mean radius by about ½ of its variance (~1e-4): the mean radius stays within 1e-3 of 1. The
// vertices and the connectivity stay the user's.
TEST(FeatureSize, SmoothsVertexNoiseOffASphereAndKeepsItsRadius) {
  const TriMesh clean = shapes::icosphere(1, 4);
  const double ell = meanEdgeLength(Topology(clean.vertexCount(), clean.faces), clean.positions);
  TriMesh m = test::ballJittered(clean, 0.2 * ell, 3);
  auto radial = [](const TriMesh& mesh, double& mean) {
    double sum = 0, sum2 = 0;
    for (const Vec3& p : mesh.positions) sum += p.norm(), sum2 += (p.norm() - 1) * (p.norm() - 1);
    mean = sum / mesh.vertexCount();
    return std::sqrt(sum2 / mesh.vertexCount());
  };
  double meanBefore = 0, meanAfter = 0;
  const double before = radial(m, meanBefore);
  const std::vector<Face> faces = m.faces;
  FlowOptions o;
  o.featureSize = 5 * ell;
  const FlowReport r = fair(m, o);
  EXPECT_EQ(r.stop, StopReason::FeatureSize);
  EXPECT_EQ(m.faces, faces);
  const double after = radial(m, meanAfter);
  EXPECT_LE(after, 0.4 * before) << "radial RMS " << before << " -> " << after;
  EXPECT_NEAR(meanAfter, 1, 1e-3);
}

// The smallest amount that makes sense, two mean edge lengths (the shortest ripple a mesh carries),
// acts: on a 2,562-vertex sphere with radial vertex noise (white: most of it at the mesh's scale)
// it takes off more than a third of the noise (measured: 42 %; one edge length 5 %, three 66 %).
// Before the amount's time was set so that ripples of its size lose 99 % (they lost 1/e), two edge
// lengths took off 16 %.
TEST(FeatureSize, TwoEdgeLengthsAct) {
  TriMesh m = shapes::icosphere(1, 4);
  const double ell = meanEdgeLength(Topology(m.vertexCount(), m.faces), m.positions);
  shapes::addRadialNoise(m, 0.1 * ell, 3);
  auto spread = [](const TriMesh& mesh) {
    double sum = 0, sum2 = 0;
    for (const Vec3& p : mesh.positions) sum += p.norm();
    const double mean = sum / mesh.vertexCount();
    for (const Vec3& p : mesh.positions) sum2 += (p.norm() - mean) * (p.norm() - mean);
    return std::sqrt(sum2 / mesh.vertexCount());
  };
  const double before = spread(m);
  FlowOptions o;
  o.featureSize = 2 * ell;
  ASSERT_EQ(fair(m, o).stop, StopReason::FeatureSize);
  EXPECT_LT(spread(m), 2.0 / 3 * before);
}

// The amount is a flow time: zero amount, no limit; the flow time reached is the one asked for.
TEST(FeatureSize, RunsForTheFlowTimeOfTheSize) {
  TriMesh m = bumpySphere().mesh;
  FlowOptions o;
  o.featureSize = 0.1;
  const FlowReport r = fair(m, o);
  ASSERT_EQ(r.stop, StopReason::FeatureSize);
  const double t = 2 * std::log(100.0) * std::pow(0.1 / (2 * M_PI), 4);  // ripples of 0.1 lose 99 %
  EXPECT_NEAR(r.history.back().time, t, 1e-6 * t);
}

TEST(FeatureSize, RejectsANegativeSizeAndTheBilaplacian) {
  TriMesh m = shapes::icosphere(1, 2);
  FlowOptions o;
  o.featureSize = -1;
  EXPECT_THROW(fair(m, o), InvalidInputError);
  o.featureSize = 0.1;
  o.flow = FlowType::Bilaplacian;
  EXPECT_THROW(fair(m, o), InvalidInputError);
}

// With uniform operators (AmountOperators::Graph, a rough scan's) the amount is twiced: the filter
// g, then g on what it took away, a response 1 − (1 − g)². On a round sphere the positions are an
// eigenvector of the operator, L X = μ X with L = M⁻¹C, nearly: μ is measured here from the uniform
// weights 1/√3 and areas faces·(√3/4)ℓ̄²/3 (mean 2.01, 2/R² on a round sphere; 1.18 to 2.40 from
// vertex to vertex, the icosphere's edges being uneven), and each of the four implicit steps scales
// the mean radius by 1/(1 + τ/2 μ²): g once shrinks it by s = 1 − (1 + τ/2 μ²)⁻⁴, twiced by s².
// The amount is chosen for s = 10 %: the sphere must shrink by 1 % (within 10 % of it), not by
// 10 %. Measured: 0.994 %; with the second pass taken out, 9.95 %.
TEST(FeatureSize, UniformOperatorsTwiceTheAmount) {
  TriMesh m = shapes::icosphere(1, 4);
  const Topology topo(m.vertexCount(), m.faces);
  const double ell = meanEdgeLength(topo, m.positions);
  std::vector<int> faces(m.vertexCount(), 0);
  for (const Face& f : m.faces)
    for (int v : f) ++faces[v];
  std::vector<Vec3> lx(m.vertexCount(), Vec3::Zero());
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto [a, b] = topo.edgeVertices(e);
    const Vec3 d = (m.positions[a] - m.positions[b]) / std::sqrt(3.0);
    lx[a] += d, lx[b] -= d;
  }
  double mu = 0;
  for (int v = 0; v < m.vertexCount(); ++v)
    mu += lx[v].dot(m.positions[v]) / (faces[v] * std::sqrt(3.0) / 12 * ell * ell) / m.positions[v].squaredNorm();
  mu /= m.vertexCount();
  const double once = 0.1;
  const double tau = 2 * (std::pow(1 - once, -0.25) - 1) / (mu * mu);  // (1 + τ/2 μ²)⁻⁴ = 1 − s
  const double flowTime = 4 * tau;                                    // the amount's four steps
  FlowOptions o;
  o.featureSize = 2 * M_PI * std::pow(flowTime / (2 * std::log(100.0)), 0.25);
  o.amountOperators = AmountOperators::Graph;
  const double radiusBefore = 1;
  ASSERT_EQ(fair(m, o).stop, StopReason::FeatureSize);
  double radius = 0;
  for (const Vec3& p : m.positions) radius += p.norm();
  radius /= m.vertexCount();
  const double shrink = radiusBefore - radius;
  EXPECT_NEAR(shrink, once * once, 0.1 * once * once) << "once would shrink it by " << once;
}
