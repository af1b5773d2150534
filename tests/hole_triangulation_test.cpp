// A hole's border and its first fill (restoration/hole_boundary, hole_triangulation): boundary
// loops walked against their faces, Liepa's minimum-weight triangulation without new vertices.
#include "hole_patches.h"
#include "test_meshes.h"

#include <elastica/shapes.h>
#include <elastica/topology.h>
#include "restoration/hole_boundary.h"
#include "restoration/hole_triangulation.h"

#include <gtest/gtest.h>

using namespace elastica;

TEST(HoleBoundary, LoopsRunAgainstTheirFaces) {
  const TriMesh m = shapes::grid(4, 3);
  const Topology topo(m.vertexCount(), m.faces);
  const auto loops = findHoleLoops(topo);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].edgeCount(), 2 * (4 + 3));
  EXPECT_FALSE(loops[0].pinched);
  // A grid with +z normals is counter-clockwise seen from +z; its hole (the outside) runs clockwise.
  double signedArea = 0;
  const auto& v = loops[0].vertices;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = m.positions[v[i]];
    const Vec3& b = m.positions[v[(i + 1) % v.size()]];
    signedArea += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_LT(signedArea, 0);
}

TEST(HoleTriangulation, ClosesAPlanarHoleConsistently) {
  const TriMesh cut = test::cutAway(shapes::grid(8, 8), [](const Vec3& p) { return (p - Vec3(4, 4, 0)).norm() < 2.5; });
  const Topology topo(cut.vertexCount(), cut.faces);
  ASSERT_EQ(findHoleLoops(topo).size(), 2u);  // the grid's rim and the hole
  const HoleLoop hole = test::smallestHole(topo);
  const auto tris = triangulateHole(cut.positions, hole, [&](int a, int b) { return test::joined(topo, a, b); });
  ASSERT_TRUE(tris.has_value());
  EXPECT_EQ(static_cast<int>(tris->size()), hole.edgeCount() - 2);
  TriMesh closed = cut;
  closed.faces.insert(closed.faces.end(), tris->begin(), tris->end());
  const Topology after(closed.vertexCount(), closed.faces);  // throws on a non-manifold edge
  EXPECT_EQ(after.inconsistentEdgeCount(), 0);
  EXPECT_EQ(after.boundaryEdgeCount(), topo.boundaryEdgeCount() - hole.edgeCount());
  for (const Face& f : *tris) {  // a flat hole is filled flat, facing +z like the grid
    const Vec3 n = (closed.positions[f[1]] - closed.positions[f[0]]).cross(closed.positions[f[2]] - closed.positions[f[0]]);
    EXPECT_GT(n.z(), 0);
  }
}
