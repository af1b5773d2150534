// SPDX-License-Identifier: GPL-3.0-or-later
// Submeshes (mesh/submesh): the piece of a mesh within k face-rings of some vertices, with
// maps back to the whole; hole filling works on such pieces.
#include "test_meshes.h"

#include <elastica/shapes.h>
#include "mesh/submesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

using namespace elastica;

namespace {

// The faces within `rings` face-rings of `seeds`, by brute force over all faces: ring 1 = the faces
// using a seed; ring r + 1 adds the faces using any vertex of ring r's faces.
std::set<int> facesWithinRings(const TriMesh& m, const std::vector<int>& seeds, int rings) {
  std::set<int> vertices(seeds.begin(), seeds.end()), faces;
  for (int r = 0; r < rings; ++r) {
    for (int f = 0; f < m.faceCount(); ++f)
      for (int v : m.faces[f])
        if (vertices.count(v)) faces.insert(f);
    for (int f : faces) vertices.insert(m.faces[f].begin(), m.faces[f].end());
  }
  return faces;
}

}  // namespace

// The maps round-trip: local face f is whole face face[f] with its corners mapped through vertex[],
// positions are copied bit for bit, faces keep their order, vertices come in order of first use,
// and the faces are exactly those within k rings (checked against brute force for k = 1..3).
TEST(Submesh, MapsRoundTripAndRingsAreFaceRings) {
  const TriMesh m = test::jittered(shapes::torus(3, 1, 24, 12), 0.05, 2);
  const VertexFaces adjacency(m.vertexCount(), m.faces);
  const std::vector<int> seeds = {5, 6, 100};
  std::size_t previous = 0;
  for (int rings = 1; rings <= 3; ++rings) {
    const Submesh sub = extractSubmesh(m, adjacency, seeds, rings);
    const std::set<int> expected = facesWithinRings(m, seeds, rings);
    EXPECT_EQ(std::set<int>(sub.face.begin(), sub.face.end()), expected) << rings;
    EXPECT_GT(sub.face.size(), previous) << rings;
    previous = sub.face.size();
    EXPECT_TRUE(std::is_sorted(sub.face.begin(), sub.face.end()));
    ASSERT_EQ(sub.mesh.faces.size(), sub.face.size());
    ASSERT_EQ(sub.mesh.positions.size(), sub.vertex.size());
    for (std::size_t f = 0; f < sub.face.size(); ++f)
      for (int k = 0; k < 3; ++k) EXPECT_EQ(sub.vertex[sub.mesh.faces[f][k]], m.faces[sub.face[f]][k]) << f;
    for (std::size_t v = 0; v < sub.vertex.size(); ++v) EXPECT_EQ(sub.mesh.positions[v], m.positions[sub.vertex[v]]) << v;
    // In order of first use: scanning the local faces meets local vertices 0, 1, 2, … in turn.
    int next = 0;
    for (const Face& t : sub.mesh.faces)
      for (int v : t) {
        EXPECT_LE(v, next);
        if (v == next) ++next;
      }
    EXPECT_EQ(next, static_cast<int>(sub.vertex.size()));
    EXPECT_EQ(std::set<int>(sub.vertex.begin(), sub.vertex.end()).size(), sub.vertex.size()) << "no vertex twice";
  }
}

// Enough rings take the whole connected mesh: the same faces in the same order, vertices renumbered.
TEST(Submesh, ManyRingsGiveTheWholeMesh) {
  const TriMesh m = shapes::icosphere(1.0, 1);
  const Submesh sub = extractSubmesh(m, VertexFaces(m.vertexCount(), m.faces), {0}, 100);
  ASSERT_EQ(sub.face.size(), m.faces.size());
  for (std::size_t f = 0; f < sub.face.size(); ++f) EXPECT_EQ(sub.face[f], static_cast<int>(f));
  EXPECT_EQ(sub.vertex.size(), m.positions.size());
}
