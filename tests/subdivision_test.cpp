// 1-to-4 midpoint subdivision (the coarse-to-fine schedule's refinement step).
#include "test_meshes.h"

#include <elastica/shapes.h>
#include <elastica/subdivision.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

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
