// SPDX-License-Identifier: GPL-3.0-or-later
// A hole's border and its first fill (restoration/hole_boundary, hole_triangulation): boundary
// loops walked against their faces, Liepa's minimum-weight triangulation without new vertices.
#include "hole_patches.h"
#include "test_meshes.h"

#include <elastica/shapes.h>
#include <elastica/topology.h>
#include "restoration/hole_boundary.h"
#include "restoration/hole_triangulation.h"

#include <gtest/gtest.h>

#include <cmath>

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

// A planar hole (in a grid facing +z) closed by triangulateHole: n − 2 triangles, a consistent
// manifold, all facing +z. The triangles of any triangulation of the border sum to the hole's
// signed area, so all of them facing +z means each point of the hole is covered once and nothing
// outside it is covered.
void expectPlanarFill(const TriMesh& cut, int minimumEdges) {
  const Topology topo(cut.vertexCount(), cut.faces);
  const HoleLoop hole = test::smallestHole(topo);
  ASSERT_GT(hole.edgeCount(), minimumEdges);
  const auto tris = triangulateHole(cut.positions, hole, [&](int a, int b) { return test::joined(topo, a, b); });
  ASSERT_TRUE(tris.has_value());
  EXPECT_EQ(static_cast<int>(tris->size()), hole.edgeCount() - 2);
  TriMesh closed = cut;
  closed.faces.insert(closed.faces.end(), tris->begin(), tris->end());
  const Topology after(closed.vertexCount(), closed.faces);  // throws on a non-manifold edge
  EXPECT_EQ(after.inconsistentEdgeCount(), 0);
  EXPECT_EQ(after.boundaryEdgeCount(), topo.boundaryEdgeCount() - hole.edgeCount());
  int facingDown = 0;
  for (const Face& f : *tris) {
    const Vec3 n = (closed.positions[f[1]] - closed.positions[f[0]]).cross(closed.positions[f[2]] - closed.positions[f[0]]);
    facingDown += n.z() <= 0;
  }
  EXPECT_EQ(facingDown, 0);
}

TEST(HoleTriangulation, ClosesAPlanarHoleConsistently) {
  const TriMesh cut = test::cutAway(shapes::grid(8, 8), [](const Vec3& p) { return (p - Vec3(4, 4, 0)).norm() < 2.5; });
  ASSERT_EQ(findHoleLoops(Topology(cut.vertexCount(), cut.faces)).size(), 2u);  // the grid's rim and the hole
  expectPlanarFill(cut, 3);
}

// Borders of more than 100 edges are cut by chords before Liepa's O(n³) search: each chord must
// stay inside the hole.
TEST(HoleTriangulation, LongRoundBorderIsSplitInsideTheHole) {
  expectPlanarFill(test::cutAway(shapes::grid(60, 60), [](const Vec3& p) { return (p - Vec3(30, 30, 0)).norm() < 24; }), 150);
}

// A C-shaped hole whose two tips nearly touch: the shortest chord that halves its border runs
// across the gap between the tips, over the mesh; it must be refused (it leaves its ends away from
// the hole's side of the faces there).
TEST(HoleTriangulation, LongCShapedBorderIsNotCutAcrossItsGap) {
  const Vec3 centre(40, 40, 0);
  expectPlanarFill(test::cutAway(shapes::grid(80, 80), [&](const Vec3& p) {
                     const Vec3 d = p - centre;
                     const double r = d.norm(), angle = std::atan2(d.y(), d.x());
                     return r > 9 && r < 20 && std::abs(angle) > 0.12;
                   }),
                   150);
}
