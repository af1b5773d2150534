// SPDX-License-Identifier: GPL-3.0-or-later
// MovingRegion: the topology and the roles follow the mesh, the selection and the mode; they are
// kept while only positions move and built again after a connectivity edit.
#include <elastica/shapes.h>
#include <elastica/subdivision.h>
#include "flow/moving_region.h"

#include <gtest/gtest.h>

using namespace elastica;

namespace {

// What the region's caches must equal: a topology and roles built afresh.
void expectFresh(const MovingRegion& region) {
  const Topology fresh(region.mesh().vertexCount(), region.mesh().faces);
  const VertexRoles roles = assignRoles(fresh, &region.selection(), region.mode());
  EXPECT_EQ(region.topology().vertexCount(), fresh.vertexCount());
  EXPECT_EQ(region.topology().edgeCount(), fresh.edgeCount());
  EXPECT_EQ(region.topology().boundaryEdgeCount(), fresh.boundaryEdgeCount());
  EXPECT_EQ(region.roles().free, roles.free);
  EXPECT_EQ(region.roles().active, roles.active);
  EXPECT_EQ(region.roles().freeCount, roles.freeCount);
}

}  // namespace

TEST(MovingRegion, CachesFollowTheMeshAndTheSelection) {
  const TriMesh grid = shapes::grid(8, 8);
  std::vector<std::uint8_t> selection(grid.faces.size(), 0);
  for (std::size_t f = 0; f < selection.size() / 2; ++f) selection[f] = 1;
  MovingRegion region(grid, selection, BoundaryMode::Fixed);
  expectFresh(region);
  const Topology* before = &region.topology();
  // Moving positions keeps them (the same objects).
  region.positions()[0] += Vec3(0, 0, 0.1);
  region.movePositions([](TriMesh& mesh) { mesh.positions[1] += Vec3(0, 0, 0.1); });
  EXPECT_EQ(&region.topology(), before);
  // An edit that reports no change keeps them too.
  EXPECT_FALSE(region.edit([](TriMesh&, std::vector<std::uint8_t>&) { return false; }));
  EXPECT_EQ(&region.topology(), before);
  // A subdivision of the selection: built again, for the new mesh.
  const int facesBefore = region.mesh().faceCount();
  EXPECT_TRUE(region.edit([](TriMesh& mesh, std::vector<std::uint8_t>& sel) {
    subdivideMidpointRegion(mesh, sel);
    return true;
  }));
  EXPECT_GT(region.mesh().faceCount(), facesBefore);
  EXPECT_EQ(region.selection().size(), region.mesh().faces.size());
  expectFresh(region);
}

TEST(MovingRegion, ACopyTakesTheCachesAndReleaseEmpties) {
  MovingRegion region(shapes::icosphere(1.0, 1), {}, BoundaryMode::Fixed);
  const int freeCount = region.roles().freeCount;
  EXPECT_EQ(freeCount, region.mesh().vertexCount());  // closed, all selected: everything moves
  MovingRegion copy = region.copyTakingCaches();
  EXPECT_EQ(copy.roles().freeCount, freeCount);
  EXPECT_EQ(copy.mesh().positions, region.mesh().positions);
  expectFresh(region);  // built again on demand
  const TriMesh out = region.release();
  EXPECT_EQ(out.vertexCount(), copy.mesh().vertexCount());
  EXPECT_EQ(region.mesh().vertexCount(), 0);
  EXPECT_TRUE(region.selection().empty());
}
