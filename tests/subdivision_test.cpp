// SPDX-License-Identifier: GPL-3.0-or-later
// 1-to-4 midpoint subdivision (the coarse-to-fine schedule's refinement step), of the whole mesh
// and of a region (fair() on a selection).
#include "test_meshes.h"

#include <elastica/errors.h>
#include <elastica/shapes.h>
#include <elastica/subdivision.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <vector>

using namespace elastica;

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

namespace {

double area(const TriMesh& m, const Face& f) {
  return 0.5 * (m.positions[f[1]] - m.positions[f[0]]).cross(m.positions[f[2]] - m.positions[f[0]]).norm();
}

// A face as its vertex cycle starting at its smallest index (the same triangle, same orientation).
Face canonical(Face f) {
  std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return f;
}

}  // namespace

// Subdividing a region ("Affect only selected faces"): the region's faces split 1-to-4, and each
// face sharing one, two or three edges with it splits into 2, 3 or 4 so that no vertex hangs on
// an edge; every other face stays as it was, at its index; no vertex moves.
TEST(Subdivision, RegionOnlyStaysConformingAndKeepsTheRest) {
  TriMesh m = test::jittered(shapes::torus(3, 1, 12, 6), 0.1, 9);
  const TriMesh before = m;
  const Topology t(m.vertexCount(), m.faces);
  std::vector<std::uint8_t> flags(m.faceCount());
  for (int f = 0; f < m.faceCount(); ++f) flags[f] = (f * 7919) % 10 < 3;  // scattered: every kind of neighbour
  const std::vector<std::uint8_t> region = flags;

  // What to expect, from the input's edges: which are the region's, and how many each face has.
  int regionEdges = 0, expectedFaces = 0, flagged = 0;
  std::vector<int> cutEdges(m.faceCount(), 0);  // per face: its edges that are the region's
  for (int e = 0; e < t.edgeCount(); ++e) {
    const auto& corners = t.edgeOppositeCorners(e);
    const bool inRegion = region[corners[0] / 3] || (corners[1] >= 0 && region[corners[1] / 3]);
    if (!inRegion) continue;
    ++regionEdges;
    for (int c : corners)
      if (c >= 0) ++cutEdges[c / 3];
  }
  std::array<int, 4> neighbours{};  // unflagged faces by number of region edges
  for (int f = 0; f < m.faceCount(); ++f) {
    const int cuts = cutEdges[f];
    flagged += region[f];
    if (!region[f]) ++neighbours[cuts];
    expectedFaces += region[f] ? 4 : 1 + cuts;
  }
  for (int cuts = 0; cuts < 4; ++cuts) ASSERT_GT(neighbours[cuts], 0) << "no unflagged face with " << cuts << " cut edges";

  subdivideMidpointRegion(m, flags);
  EXPECT_EQ(m.vertexCount(), before.vertexCount() + regionEdges);
  EXPECT_EQ(m.faceCount(), expectedFaces);
  ASSERT_EQ(flags.size(), m.faces.size());
  EXPECT_EQ(std::count(flags.begin(), flags.end(), 1), 4 * flagged);
  for (int v = 0; v < before.vertexCount(); ++v) EXPECT_EQ(m.positions[v], before.positions[v]);
  // Conforming and oriented as before: the closed torus stays closed, every edge on two faces
  // traversed in opposite directions, with the same Euler characteristic and area.
  const Topology t2(m.vertexCount(), m.faces);
  EXPECT_EQ(t2.boundaryEdgeCount(), 0);
  EXPECT_EQ(t2.inconsistentEdgeCount(), 0);
  EXPECT_EQ(t2.eulerCharacteristic(), t.eulerCharacteristic());
  double a0 = 0, a1 = 0, r0 = 0, r1 = 0;
  for (int f = 0; f < before.faceCount(); ++f) a0 += area(before, before.faces[f]), r0 += region[f] ? area(before, before.faces[f]) : 0;
  for (int f = 0; f < m.faceCount(); ++f) a1 += area(m, m.faces[f]), r1 += flags[f] ? area(m, m.faces[f]) : 0;
  EXPECT_NEAR(a1, a0, 1e-12 * a0);
  EXPECT_NEAR(r1, r0, 1e-12 * r0);  // the flagged children cover exactly the region
  // Faces without a region edge are untouched, at their index.
  for (int f = 0; f < before.faceCount(); ++f)
    if (cutEdges[f] == 0) { EXPECT_EQ(m.faces[f], before.faces[f]) << "face " << f; }
}

// The whole mesh as the region: the same triangles as subdivideMidpoint.
TEST(Subdivision, RegionOfEveryFaceIsTheWholeSubdivision) {
  TriMesh whole = test::jittered(shapes::icosphere(1.0, 1), 0.05, 3);
  TriMesh region = whole;
  std::vector<std::uint8_t> flags(region.faceCount(), 1);
  subdivideMidpoint(whole);
  subdivideMidpointRegion(region, flags);
  EXPECT_EQ(region.positions, whole.positions);
  std::vector<Face> a, b;
  for (const Face& f : whole.faces) a.push_back(canonical(f));
  for (const Face& f : region.faces) b.push_back(canonical(f));
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
  EXPECT_EQ(std::count(flags.begin(), flags.end(), 1), region.faceCount());
  std::vector<std::uint8_t> wrong(3, 1);
  EXPECT_THROW(subdivideMidpointRegion(region, wrong), InvalidInputError);
}

// Loop's masks on the octahedron (every vertex of valence 4, so β = 3/32): an old vertex v goes to
// (1 − 4β) v + β Σ ring = 5/8 v (its ring sums to 0), an edge vertex to 3/8 (a + b) + 1/8 (c + d)
// = 3/8 (a + b) (its two opposite corners are antipodal). The faces are the midpoint scheme's.
TEST(Subdivision, LoopMasksOnTheOctahedron) {
  TriMesh m;
  m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  const TriMesh before = m;
  TriMesh midpoint = m;
  subdivideMidpoint(midpoint);
  subdivideLoop(m);
  ASSERT_EQ(m.vertexCount(), 6 + 12);
  ASSERT_EQ(m.faceCount(), 32);
  for (int v = 0; v < 6; ++v) EXPECT_LT((m.positions[v] - 0.625 * before.positions[v]).norm(), 1e-15) << v;
  for (int v = 6; v < m.vertexCount(); ++v) {
    EXPECT_NEAR(m.positions[v].norm(), 0.375 * std::sqrt(2.0), 1e-15) << v;  // 3/8 |a + b|, a ⟂ b
    EXPECT_NEAR(m.positions[v].cwiseAbs().sum(), 0.75, 1e-15) << v;          // two coordinates ±3/8
  }
  // The same connectivity as the midpoint scheme: each face's corners, by position class.
  const Topology t(m.vertexCount(), m.faces);
  EXPECT_EQ(t.eulerCharacteristic(), 2);
  EXPECT_EQ(t.boundaryEdgeCount(), 0);
  for (int f = 0; f < m.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(m.faces[f][k] < 6, midpoint.faces[f][k] < 6) << f;
}

TEST(Subdivision, LoopRefusesAMeshWithABorder) {
  TriMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.faces = {{0, 1, 2}};
  EXPECT_THROW(subdivideLoop(m), InvalidInputError);
}

// Loop's masks on the flagged faces only: the connectivity is subdivideMidpointRegion's; a vertex
// all of whose faces are flagged and an edge vertex between two flagged faces take Loop's masks
// (with every face flagged on a closed mesh: subdivideLoop's positions); every other vertex stays
// where it was, every other edge vertex at its edge's midpoint.
TEST(Subdivision, LoopOnARegionSmoothsInsideAndKeepsTheRest) {
  const TriMesh input = test::jittered(shapes::torus(3, 1, 12, 6), 0.1, 9);
  {
    TriMesh all = input, loop = input;
    std::vector<std::uint8_t> flags(all.faceCount(), 1);
    subdivideLoopRegion(all, flags);
    subdivideLoop(loop);
    ASSERT_EQ(all.vertexCount(), loop.vertexCount());
    std::vector<std::array<double, 3>> a, b;
    for (int v = 0; v < all.vertexCount(); ++v) {
      a.push_back({all.positions[v].x(), all.positions[v].y(), all.positions[v].z()});
      b.push_back({loop.positions[v].x(), loop.positions[v].y(), loop.positions[v].z()});
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
  }
  TriMesh m = input, midpoint = input;
  std::vector<std::uint8_t> flags(m.faceCount()), midpointFlags;
  for (int f = 0; f < m.faceCount(); ++f) flags[f] = m.positions[m.faces[f][0]].x() > 0.5;  // a band of the torus
  midpointFlags = flags;
  const std::vector<std::uint8_t> before = flags;
  subdivideLoopRegion(m, flags);
  subdivideMidpointRegion(midpoint, midpointFlags);
  EXPECT_EQ(m.faces, midpoint.faces);
  EXPECT_EQ(flags, midpointFlags);
  // Which old vertices have every face flagged, and which edges two flagged faces.
  const Topology t(input.vertexCount(), input.faces);
  int smoothed = 0, kept = 0;
  for (int v = 0; v < input.vertexCount(); ++v) {
    bool inside = true;
    for (int k = t.cornerBegin(v); k < t.cornerEnd(v); ++k) inside = inside && before[t.corner(k) / 3];
    if (!inside) {
      EXPECT_EQ(m.positions[v], input.positions[v]) << v;
      ++kept;
      continue;
    }
    const int n = t.valence(v);
    const double beta = n == 3 ? 3.0 / 16 : 3.0 / (8.0 * n);
    Vec3 ring = Vec3::Zero();
    for (int k = t.ringBegin(v); k < t.ringEnd(v); ++k) ring += input.positions[t.ringVertex(k)];
    EXPECT_LT((m.positions[v] - ((1 - n * beta) * input.positions[v] + beta * ring)).norm(), 1e-12) << v;
    ++smoothed;
  }
  EXPECT_GT(smoothed, 0);
  EXPECT_GT(kept, 0);
  // New vertices: Loop's edge point where both faces were flagged, else the midpoint scheme's.
  int edgePoints = 0, midpoints = 0;
  for (int v = input.vertexCount(); v < m.vertexCount(); ++v) {
    if (m.positions[v] == midpoint.positions[v]) ++midpoints;
    else ++edgePoints;
  }
  EXPECT_GT(edgePoints, 0);
  EXPECT_GT(midpoints, 0);
  int interiorEdges = 0;
  for (int e = 0; e < t.edgeCount(); ++e) {
    const auto& oc = t.edgeOppositeCorners(e);
    interiorEdges += oc[1] >= 0 && before[oc[0] / 3] && before[oc[1] / 3];
  }
  EXPECT_EQ(edgePoints, interiorEdges);
}
