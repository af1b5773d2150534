// SPDX-License-Identifier: GPL-3.0-or-later
// Dynamic connectivity (mesh/edge_flips): Delaunay edge flips among the moving vertices.
#include <elastica/geometry.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>
#include "mesh/edge_flips.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace elastica;

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
    if (allMovable) { EXPECT_LE(g.cornerAngle(oc[0]) + g.cornerAngle(oc[1]), M_PI + 1e-6) << "edge " << e; }
  }
  // Faces with a fixed vertex are untouched.
  for (int f = 0; f < m.faceCount(); ++f) {
    bool fixedVertex = false;
    for (int v : before.faces[f]) fixedVertex = fixedVertex || !movable[v];
    if (fixedVertex) { EXPECT_EQ(m.faces[f], before.faces[f]) << f; }
  }
}

// Given the mesh's adjacency (a flow state's), the flips build none and make the same faces; an
// adjacency of other faces is not read.
TEST(EdgeFlips, TheCallersAdjacencyIsReadNotBuilt) {
  TriMesh m = shapes::grid(10, 10, 1.0);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-0.45, 0.45);
  for (Vec3& p : m.positions)
    if (p.x() > 0 && p.x() < 10 && p.y() > 0 && p.y() < 10) p += Vec3(u(rng), u(rng), 0.1 * u(rng));
  std::vector<std::uint8_t> movable(m.vertexCount(), 0);
  for (int v = 0; v < m.vertexCount(); ++v) movable[v] = m.positions[v].x() > 2.5 && m.positions[v].x() < 7.5;
  TriMesh built = m;
  const int flips = flipToDelaunay(built, movable);
  EXPECT_GT(flips, 5);
  const Topology current(m.vertexCount(), m.faces);
  TriMesh given = m;
  Topology::resetLargestBuilt();
  EXPECT_EQ(flipToDelaunay(given, &current, movable), flips);
  EXPECT_EQ(Topology::largestBuilt(), 0);
  EXPECT_EQ(given.faces, built.faces);
  TriMesh other = m;  // `current` is no longer its adjacency after the flips above
  other.faces = built.faces;
  EXPECT_EQ(flipToDelaunay(other, &current, movable), flipToDelaunay(built, movable));
  EXPECT_EQ(other.faces, built.faces);
  EXPECT_GT(Topology::largestBuilt(), 0);
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
