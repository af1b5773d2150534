// SPDX-License-Identifier: GPL-3.0-or-later
#include "test_meshes.h"

#include <elastica/errors.h>
#include <elastica/geometry.h>
#include <elastica/laplacian.h>
#include <elastica/shapes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace elastica;

namespace {

std::vector<TriMesh> testMeshes() {
  return {shapes::icosphere(2.0, 3), shapes::torus(3, 1, 32, 16), shapes::grid(6, 5, 0.5),
          test::jittered(shapes::icosphere(1.0, 2), 0.02), test::jittered(shapes::torus(2, 0.7, 20, 9), 0.05, 7)};
}

}  // namespace

// Mixed and barycentric areas both partition each face's area among its corners, so the vertex
// areas sum to the surface area on every mesh (libigl's mass-matrix identity).
TEST(Geometry, VertexAreasSumToSurfaceArea) {
  for (const TriMesh& m : testMeshes()) {
    const Topology t(m.vertexCount(), m.faces);
    for (VertexArea type : {VertexArea::Mixed, VertexArea::Barycentric}) {
      const Geometry g = computeGeometry(t, m.positions, type);
      const double total = std::accumulate(g.faceArea.begin(), g.faceArea.end(), 0.0);
      const double sum = std::accumulate(g.vertexArea.begin(), g.vertexArea.end(), 0.0);
      EXPECT_NEAR(sum, total, 1e-12 * total);
      for (double a : g.vertexArea) EXPECT_GT(a, 0);
    }
  }
}

TEST(Geometry, AnglesOfEachFaceSumToPi) {
  for (const TriMesh& m : testMeshes()) {
    const Topology t(m.vertexCount(), m.faces);
    const Geometry g = computeGeometry(t, m.positions);
    for (int f = 0; f < t.faceCount(); ++f)
      EXPECT_NEAR(g.cornerAngle(3 * f) + g.cornerAngle(3 * f + 1) + g.cornerAngle(3 * f + 2), M_PI, 1e-12);
  }
}

TEST(Geometry, SphereNormalsAreRadialAndOutward) {
  const TriMesh m = shapes::icosphere(3.0, 3);
  const Topology t(m.vertexCount(), m.faces);
  const Geometry g = computeGeometry(t, m.positions);
  for (int v = 0; v < t.vertexCount(); ++v) {
    EXPECT_NEAR(g.vertexNormal[v].norm(), 1.0, 1e-12);
    EXPECT_GT(g.vertexNormal[v].dot(m.positions[v].normalized()), 0.9999);
  }
}

// The cotangent Laplacian reproduces linear functions exactly on a planar mesh (any triangles),
// and annihilates constants everywhere.
TEST(Laplacian, ExactOnLinearFunctionsInThePlane) {
  TriMesh m = test::jittered(shapes::grid(8, 8, 1.0), 0.2, 3);
  for (Vec3& p : m.positions) p.z() = 0;
  const Topology t(m.vertexCount(), m.faces);
  const Geometry g = computeGeometry(t, m.positions);
  std::vector<double> f(m.vertexCount()), lf;
  for (int v = 0; v < m.vertexCount(); ++v) f[v] = 2.0 * m.positions[v].x() - 3.0 * m.positions[v].y() + 5.0;
  cotanLaplacian(t, g, f, lf);
  std::vector<Vec3> lp;
  cotanLaplacian(t, g, m.positions, lp);
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (t.isBoundaryVertex(v)) continue;
    EXPECT_NEAR(lf[v], 0.0, 1e-12);
    EXPECT_NEAR(lp[v].norm(), 0.0, 1e-12);
  }
  std::vector<double> ones(m.vertexCount(), 1.0), l1;
  cotanLaplacian(t, g, ones, l1);
  for (double x : l1) EXPECT_EQ(x, 0.0);
}

// Δ_B P = 2H N: on a sphere of radius r the Laplacian of the positions has length 2/r and
// points inward.
TEST(Laplacian, MeanCurvatureVectorOfSphere) {
  const double r = 2.0;
  const TriMesh m = shapes::icosphere(r, 4);
  const Topology t(m.vertexCount(), m.faces);
  const Geometry g = computeGeometry(t, m.positions);
  std::vector<Vec3> lp;
  cotanLaplacian(t, g, m.positions, lp);
  for (int v = 0; v < m.vertexCount(); ++v) {
    EXPECT_NEAR(lp[v].norm(), 2 / r, 0.005 * 2 / r);
    EXPECT_LT(lp[v].normalized().dot(g.vertexNormal[v]), -0.9999);
  }
}

// With vertex flags, the flagged vertices get exactly the values of the whole computation (the
// faces and edges are all computed alike) and the others zero.
TEST(Geometry, FlaggedVerticesOnly) {
  for (const TriMesh& m : testMeshes()) {
    const Topology t(m.vertexCount(), m.faces);
    const Geometry all = computeGeometry(t, m.positions);
    std::vector<std::uint8_t> flags(m.vertexCount(), 0);
    for (int v = 0; v < m.vertexCount(); v += 3) flags[v] = 1;
    Geometry some;
    computeGeometry(t, m.positions, VertexArea::Mixed, some, &flags);
    EXPECT_EQ(some.meanEdgeLength, all.meanEdgeLength);
    EXPECT_EQ(some.faceArea, all.faceArea);
    EXPECT_EQ(some.cornerCot, all.cornerCot);
    EXPECT_EQ(some.edgeWeight, all.edgeWeight);
    for (int v = 0; v < m.vertexCount(); ++v) {
      EXPECT_EQ(some.vertexArea[v], flags[v] ? all.vertexArea[v] : 0.0);
      EXPECT_EQ(some.angleSum[v], flags[v] ? all.angleSum[v] : 0.0);
      EXPECT_EQ(some.ringArea[v], flags[v] ? all.ringArea[v] : 0.0);
      EXPECT_EQ(some.vertexNormal[v], flags[v] ? all.vertexNormal[v] : Vec3(Vec3::Zero()));
    }
    flags.pop_back();
    EXPECT_THROW(computeGeometry(t, m.positions, VertexArea::Mixed, some, &flags), InvalidInputError);
  }
}

// Kept values (GeometryKept): after some vertices move, a computation that keeps the faces and
// edges none of whose vertices moved gives the fresh computation's values bit for bit, tallies
// included; a kept face that the new floor makes degenerate is computed again. A face flagged
// though it moved keeps its old values: they are kept, not computed.
namespace {
void expectSameGeometry(const Geometry& a, const Geometry& b) {
  EXPECT_EQ(a.meanEdgeLength, b.meanEdgeLength);
  EXPECT_EQ(a.faceArea, b.faceArea);
  EXPECT_EQ(a.faceNormal, b.faceNormal);
  EXPECT_EQ(a.cornerDot, b.cornerDot);
  EXPECT_EQ(a.cornerCot, b.cornerCot);
  EXPECT_EQ(a.cornerArea, b.cornerArea);
  EXPECT_EQ(a.edgeLength, b.edgeLength);
  EXPECT_EQ(a.edgeWeight, b.edgeWeight);
  EXPECT_EQ(a.vertexArea, b.vertexArea);
  EXPECT_EQ(a.angleSum, b.angleSum);
  EXPECT_EQ(a.minFaceArea, b.minFaceArea);
  EXPECT_EQ(a.degenerate.zeroAreaFaces, b.degenerate.zeroAreaFaces);
}
}  // namespace

TEST(Geometry, KeptFacesAndEdgesGiveTheFreshValues) {
  TriMesh m = shapes::icosphere(1.0, 3);
  const Topology t(m.vertexCount(), m.faces);
  Geometry g, fresh;
  computeGeometry(t, m.positions, VertexArea::Mixed, g);
  std::vector<std::uint8_t> moved(m.vertexCount(), 0);
  for (int v = 0; v < m.vertexCount(); ++v)
    if (m.positions[v].z() > 0.5) m.positions[v] *= 1.5, moved[v] = 1;
  std::vector<std::uint8_t> keptFaces(m.faceCount()), keptEdges(t.edgeCount());
  for (int f = 0; f < m.faceCount(); ++f) keptFaces[f] = !moved[m.faces[f][0]] && !moved[m.faces[f][1]] && !moved[m.faces[f][2]];
  for (int e = 0; e < t.edgeCount(); ++e) keptEdges[e] = !moved[t.edgeVertices(e)[0]] && !moved[t.edgeVertices(e)[1]];
  computeGeometry(t, m.positions, VertexArea::Mixed, g, nullptr, {&keptFaces, &keptEdges});
  computeGeometry(t, m.positions, VertexArea::Mixed, fresh);
  expectSameGeometry(g, fresh);
  // Flagged though a corner moved: the old values stay.
  const Geometry before = g;
  const int f0 = 0;
  ASSERT_TRUE(keptFaces[f0]);
  m.positions[m.faces[f0][0]] += Vec3(0.05, 0, 0);
  computeGeometry(t, m.positions, VertexArea::Mixed, g, nullptr, {&keptFaces, nullptr});
  EXPECT_EQ(g.faceArea[f0], before.faceArea[f0]);
  computeGeometry(t, m.positions, VertexArea::Mixed, fresh);
  EXPECT_NE(fresh.faceArea[f0], before.faceArea[f0]);
}

TEST(Geometry, KeptFaceUnderTheNewFloorIsComputedAgain) {
  // A needle (0, 1, 2) of area 1.5e-12 beside a face whose far corner moves out: the mean edge
  // grows from about 1 to about 3, the floor from about 1e-12 to about 1e-11.
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 3e-12, 0}, {0.5, -1, 0}};
  m.faces = {{0, 1, 2}, {1, 0, 3}};
  const Topology t(m.vertexCount(), m.faces);
  Geometry g, fresh;
  computeGeometry(t, m.positions, VertexArea::Mixed, g);
  ASSERT_EQ(g.degenerate.zeroAreaFaces, 0u);
  m.positions[3] = Vec3(0.5, -10, 0);
  const std::vector<std::uint8_t> keptFaces = {1, 0};
  computeGeometry(t, m.positions, VertexArea::Mixed, g, nullptr, {&keptFaces, nullptr});
  computeGeometry(t, m.positions, VertexArea::Mixed, fresh);
  EXPECT_EQ(fresh.degenerate.zeroAreaFaces, 1u);
  expectSameGeometry(g, fresh);
}

TEST(Geometry, DegenerateElementsAreCountedAndFinite) {
  // A strip of 4 triangles plus a zero-area triangle (collinear) and a coincident vertex.
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {1, 0, 0} /* copy of 1 */};
  m.faces = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {0, 6, 1} /* zero area, zero-length edge */};
  const Topology t(m.vertexCount(), m.faces);
  const Geometry g = computeGeometry(t, m.positions);
  EXPECT_EQ(g.degenerate.zeroAreaFaces, 1u);
  EXPECT_EQ(g.degenerate.zeroLengthEdges, 1u);
  EXPECT_DOUBLE_EQ(g.minFaceArea, 0.5);
  for (double x : g.cornerCot) EXPECT_TRUE(std::isfinite(x));
  for (double x : g.vertexArea) EXPECT_TRUE(std::isfinite(x));
  for (const Vec3& n : g.vertexNormal) EXPECT_TRUE(n.allFinite());
}

TEST(Geometry, AllPointsCoincidentStaysFinite) {
  TriMesh m;
  m.positions = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  const Topology t(m.vertexCount(), m.faces);
  const Geometry g = computeGeometry(t, m.positions);
  EXPECT_EQ(g.degenerate.zeroAreaFaces, 2u);
  EXPECT_EQ(g.degenerate.zeroAreaVertices, 4u);
  for (double x : g.cornerCot) EXPECT_TRUE(std::isfinite(x));
  for (double w : g.edgeWeight) EXPECT_TRUE(std::isfinite(w));
}
