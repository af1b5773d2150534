// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

using namespace elastica;

TEST(Topology, IcosphereIsClosedGenusZero) {
  for (int level = 0; level <= 3; ++level) {
    const TriMesh m = shapes::icosphere(1.0, level);
    const Topology t(m.vertexCount(), m.faces);
    EXPECT_EQ(t.eulerCharacteristic(), 2);
    EXPECT_EQ(t.boundaryEdgeCount(), 0);
    EXPECT_EQ(t.inconsistentEdgeCount(), 0);
    EXPECT_EQ(t.nonManifoldVertexCount(), 0);
    EXPECT_EQ(2 * t.edgeCount(), 3 * t.faceCount());
    int valenceSum = 0;
    for (int v = 0; v < t.vertexCount(); ++v) valenceSum += t.valence(v);
    EXPECT_EQ(valenceSum, 2 * t.edgeCount());
  }
}

TEST(Topology, TorusHasEulerCharacteristicZero) {
  const TriMesh m = shapes::torus(3, 1, 24, 12);
  const Topology t(m.vertexCount(), m.faces);
  EXPECT_EQ(t.eulerCharacteristic(), 0);
  EXPECT_EQ(t.boundaryEdgeCount(), 0);
  EXPECT_EQ(t.inconsistentEdgeCount(), 0);
}

TEST(Topology, GridBoundary) {
  const int nx = 7, ny = 4;
  const TriMesh m = shapes::grid(nx, ny);
  const Topology t(m.vertexCount(), m.faces);
  EXPECT_EQ(t.boundaryEdgeCount(), 2 * (nx + ny));
  EXPECT_EQ(t.eulerCharacteristic(), 1);
  int boundaryVertices = 0;
  for (int v = 0; v < t.vertexCount(); ++v) boundaryVertices += t.isBoundaryVertex(v);
  EXPECT_EQ(boundaryVertices, 2 * (nx + ny));
}

TEST(Topology, RingAndCornersAreConsistent) {
  const TriMesh m = shapes::icosphere(1.0, 2);
  const Topology t(m.vertexCount(), m.faces);
  for (int v = 0; v < t.vertexCount(); ++v) {
    // On a closed manifold every vertex has as many incident faces as neighbours.
    EXPECT_EQ(t.cornerEnd(v) - t.cornerBegin(v), t.valence(v));
    for (int k = t.ringBegin(v); k < t.ringEnd(v); ++k) {
      const auto& ev = t.edgeVertices(t.ringEdge(k));
      EXPECT_TRUE((ev[0] == v && ev[1] == t.ringVertex(k)) || (ev[1] == v && ev[0] == t.ringVertex(k)));
    }
    for (int k = t.cornerBegin(v); k < t.cornerEnd(v); ++k) EXPECT_EQ(m.faces[t.corner(k) / 3][t.corner(k) % 3], v);
  }
  for (int e = 0; e < t.edgeCount(); ++e) {
    // The corner opposite an edge is the face's third vertex.
    for (int c : t.edgeOppositeCorners(e)) {
      ASSERT_GE(c, 0);
      const int opposite = m.faces[c / 3][c % 3];
      EXPECT_NE(opposite, t.edgeVertices(e)[0]);
      EXPECT_NE(opposite, t.edgeVertices(e)[1]);
    }
  }
}

TEST(Topology, RejectsBadIndices) {
  EXPECT_THROW(Topology(3, {{0, 1, 3}}), InvalidInputError);
  EXPECT_THROW(Topology(3, {{0, -1, 2}}), InvalidInputError);
  EXPECT_THROW(Topology(3, {{0, 1, 1}}), InvalidInputError);
}

TEST(Topology, RejectsNonManifoldEdgeWithItsVertices) {
  // Three triangles on the edge 0–1.
  try {
    Topology(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("non-manifold edge between vertices 0 and 1"), std::string::npos) << e.what();
  }
}

TEST(Topology, CountsInconsistentOrientationAndBowTies) {
  // Two triangles sharing edge 1–2, the second flipped.
  const Topology flipped(4, {{0, 1, 2}, {1, 2, 3}});
  EXPECT_EQ(flipped.inconsistentEdgeCount(), 1);
  const Topology fine(4, {{0, 1, 2}, {2, 1, 3}});
  EXPECT_EQ(fine.inconsistentEdgeCount(), 0);
  // Two triangles touching only at vertex 0.
  const Topology bowtie(5, {{0, 1, 2}, {0, 3, 4}});
  EXPECT_EQ(bowtie.nonManifoldVertexCount(), 1);
}

TEST(Topology, IsolatedVertex) {
  const Topology t(4, {{0, 1, 2}});
  EXPECT_TRUE(t.isIsolatedVertex(3));
  EXPECT_FALSE(t.isIsolatedVertex(0));
}

// rebuild() reuses the storage of an earlier topology, larger or smaller, and gives what a fresh
// one gives; a throw leaves it empty.
TEST(Topology, RebuildEqualsAFreshTopology) {
  const std::vector<TriMesh> meshes = {shapes::icosphere(1.0, 3), shapes::grid(7, 4), shapes::torus(3, 1, 24, 12),
                                       shapes::icosphere(1.0, 1)};
  Topology t;
  EXPECT_EQ(t.vertexCount(), 0);
  EXPECT_EQ(t.edgeCount(), 0);
  for (const TriMesh& m : meshes) {
    t.rebuild(m.vertexCount(), m.faces);
    const Topology fresh(m.vertexCount(), m.faces);
    ASSERT_EQ(t.edgeCount(), fresh.edgeCount());
    EXPECT_EQ(t.faces(), fresh.faces());
    EXPECT_EQ(t.boundaryEdgeCount(), fresh.boundaryEdgeCount());
    EXPECT_EQ(t.inconsistentEdgeCount(), fresh.inconsistentEdgeCount());
    EXPECT_EQ(t.byteSize(), fresh.byteSize());
    for (int e = 0; e < t.edgeCount(); ++e) {
      EXPECT_EQ(t.edgeVertices(e), fresh.edgeVertices(e));
      EXPECT_EQ(t.edgeOppositeCorners(e), fresh.edgeOppositeCorners(e));
    }
    for (int v = 0; v < t.vertexCount(); ++v) {
      ASSERT_EQ(t.ringBegin(v), fresh.ringBegin(v));
      ASSERT_EQ(t.ringEnd(v), fresh.ringEnd(v));
      for (int k = t.ringBegin(v); k < t.ringEnd(v); ++k) {
        EXPECT_EQ(t.ringVertex(k), fresh.ringVertex(k));
        EXPECT_EQ(t.ringEdge(k), fresh.ringEdge(k));
      }
      ASSERT_EQ(t.cornerBegin(v), fresh.cornerBegin(v));
      ASSERT_EQ(t.cornerEnd(v), fresh.cornerEnd(v));
      for (int k = t.cornerBegin(v); k < t.cornerEnd(v); ++k) EXPECT_EQ(t.corner(k), fresh.corner(k));
      EXPECT_EQ(t.isBoundaryVertex(v), fresh.isBoundaryVertex(v));
    }
  }
  EXPECT_THROW(t.rebuild(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}), InvalidInputError);
  EXPECT_EQ(t.vertexCount(), 0);
  EXPECT_EQ(t.faceCount(), 0);
  EXPECT_EQ(t.edgeCount(), 0);
}

// Vertices of very high valence take the general sort (more than 32 spokes): a fan of 40 faces
// around vertex 0 lists its edges and ring in increasing order, each edge's corners in face order.
TEST(Topology, HighValenceVertex) {
  const int n = 40;
  std::vector<Face> faces;
  for (int i = 0; i < n; ++i) faces.push_back({0, 1 + i, 1 + (i + 1) % n});
  const Topology t(n + 1, faces);
  EXPECT_EQ(t.valence(0), n);
  EXPECT_EQ(t.boundaryEdgeCount(), n);  // the rim
  for (int k = t.ringBegin(0) + 1; k < t.ringEnd(0); ++k) EXPECT_LT(t.ringVertex(k - 1), t.ringVertex(k));
  for (int e = 0; e < t.edgeCount(); ++e) {
    EXPECT_LT(t.edgeVertices(e)[0], t.edgeVertices(e)[1]);
    if (e > 0) {
      EXPECT_LT(t.edgeVertices(e - 1), t.edgeVertices(e));
    }
    if (!t.isBoundaryEdge(e)) {
      EXPECT_LT(t.edgeOppositeCorners(e)[0], t.edgeOppositeCorners(e)[1]);
    }
  }
}
