// SPDX-License-Identifier: GPL-3.0-or-later
// The flow's remeshing within a vertex budget (flow/mesh_quality_stage.h): the budget's formula,
// and a curvature-adaptive remeshing that leaves no more moving vertices than it is given.
#include <elastica/shapes.h>
#include "flow/mesh_quality_stage.h"
#include "flow/moving_region.h"
#include "mesh/self_intersection.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

using namespace elastica;

// Edges of 0.4/κ put κ²/(0.4² √3/2) vertices on a unit of area, ∫κ² ≤ E < 8π(g + 3) for a fair
// shape of genus g, four times that for the widening: on top of the vertices that move now.
TEST(VertexBudget, IsTheMovingVerticesPlusWhatAFairShapesCurvatureNeeds) {
  for (int genus : {0, 1, 3}) {
    const double adaptive = 4 * 8 * M_PI * (genus + 3) / (0.4 * 0.4 * std::sqrt(3.0) / 2);
    EXPECT_EQ(vertexBudget(0, genus), static_cast<long long>(std::ceil(adaptive))) << genus;
    EXPECT_EQ(vertexBudget(5000, genus), 5000 + vertexBudget(0, genus)) << genus;
  }
}

// A thin torus sampled coarsely (R/r 8, 48×8: κℓ 0.8 to 1.2) wants edges two to three times
// shorter everywhere for κℓ 0.4: without a bound the curvature-adaptive remeshing multiplies its
// vertices; within a budget it leaves at most the budget, refines still, and keeps the genus.
TEST(VertexBudget, AdaptiveRemeshingStaysWithinTheBudget) {
  const TriMesh thin = shapes::torus(8, 1, 48, 8);
  MovingRegion free(thin, {}, BoundaryMode::Fixed);
  ASSERT_TRUE(remeshMovingRegion(free, true));
  const long long unbounded = free.mesh().vertexCount();
  const long long budget = 2 * thin.vertexCount();
  ASSERT_GT(unbounded, budget);  // the bound has something to bound
  MovingRegion bounded(thin, {}, BoundaryMode::Fixed);
  ASSERT_TRUE(remeshMovingRegion(bounded, true, 1, budget));
  EXPECT_LE(bounded.mesh().vertexCount(), budget);
  EXPECT_GT(bounded.mesh().vertexCount(), thin.vertexCount());
  EXPECT_EQ(closedGenus(bounded.topology()), 1);
}

// A torus drawn as a CAD exporter would (R 3, r 1; 8 segments around the axis, 64 around the
// tube: triangles of aspect up to ~30): splitLongEdges leaves every input vertex where it was, adds
// vertices on the long edges (the longest at least halved; measured 3.06 → 1.20), keeps the genus,
// and makes no face cross. (With 6 segments the remesher's flips at the inner hexagon's corners
// made a face cross, and the split is refused: the mesh stays as it was.)
TEST(SplitLongEdges, SplitsSliversWithoutMovingTheInput) {
  const TriMesh slivers = shapes::torus(3, 1, 8, 64);
  auto longest = [](const TriMesh& m) {
    double l = 0;
    for (const Face& f : m.faces)
      for (int k = 0; k < 3; ++k) l = std::max(l, (m.positions[f[k]] - m.positions[f[(k + 1) % 3]]).norm());
    return l;
  };
  MovingRegion region(slivers, {}, BoundaryMode::Fixed);
  ASSERT_TRUE(splitLongEdges(region));
  const TriMesh& split = region.mesh();
  ASSERT_GT(split.vertexCount(), slivers.vertexCount());
  for (int v = 0; v < slivers.vertexCount(); ++v) EXPECT_EQ(split.positions[v], slivers.positions[v]) << v;
  EXPECT_LT(longest(split), 0.5 * longest(slivers));
  EXPECT_EQ(closedGenus(region.topology()), 1);
  EXPECT_FALSE(selfIntersects(split));
}

// A split has a bound: the 8×5 torus with one vertex thrown 256 edge lengths away (a fuzzed input)
// needs about 30,000 vertices to bring every edge to the target, over 64× its 40 + 2,000; the split is
// refused and the mesh kept as it came (without the bound the split was made, and the remeshings
// after it ran for minutes under the sanitizers before the flow could check its time limit).
TEST(SplitLongEdges, RefusesASplitPastItsBound) {
  TriMesh thrown = shapes::torus(3, 1, 8, 5);
  thrown.positions[7] *= 256;
  MovingRegion region(thrown, {}, BoundaryMode::Fixed);
  EXPECT_FALSE(splitLongEdges(region));
  EXPECT_EQ(region.mesh().vertexCount(), thrown.vertexCount());
  EXPECT_EQ(region.mesh().faces, thrown.faces);
}

// A fat torus whose hole is a slit (R 1, r 0.97: the hole's sides 0.06 apart, under a third of the
// median edge): a remeshing at the median face's size makes faces cross there and is refused;
// with the targets halved around the crossing faces (crossingRefinements) it resolves the gap
// where it is: no face crossing, the genus kept (femur, genus 2, has such a gap: its first
// remeshing was refused and every flow step after it).
TEST(CrossingRefinements, ResolveANarrowGapInsteadOfRefusingTheRemeshing) {
  for (int n : {24, 48}) {
    const TriMesh slit = shapes::torus(1, 0.97, n, n);
    ASSERT_FALSE(selfIntersects(slit));
    MovingRegion plain(slit, {}, BoundaryMode::Fixed);
    EXPECT_FALSE(remeshMovingRegion(plain, false)) << n;  // the case the rule is for
    MovingRegion refined(slit, {}, BoundaryMode::Fixed);
    ASSERT_TRUE(remeshMovingRegion(refined, false, 1, 0, nullptr, 4)) << n;
    EXPECT_FALSE(selfIntersects(refined.mesh())) << n;
    EXPECT_EQ(closedGenus(refined.topology()), 1) << n;
  }
}

// The isotropic edge against the thinnest feature: a round torus (R 3, r 1, 48×16) has edges a
// fifth of its tube's width, and is remeshed as it is; a thin ring drawn with long slivers (R 1,
// r 0.01, 40 segments around the axis, 4 around the tube) has a median face whose equilateral edge
// is several times its tube's width: an isotropic remeshing would step over it.
TEST(IsotropicEdgeMissesThinnest, OnlyWhereTheEdgeIsSeveralTimesThePartsThinnestFeature) {
  const MovingRegion round(shapes::torus(3, 1, 48, 16), {}, BoundaryMode::Fixed);
  EXPECT_FALSE(isotropicEdgeMissesThinnest(round));
  const MovingRegion thin(shapes::torus(1, 0.01, 40, 4), {}, BoundaryMode::Fixed);
  EXPECT_TRUE(isotropicEdgeMissesThinnest(thin));
}

// A mesh with a border, remeshed at four times its edge length (a coarse start): its fixed rows
// (the border and its neighbours) keep their faces, which the grid interleaves with the moving ones
// at the end of its face list; the remesher must still collapse (keeping those faces at their
// index, without PatchRemeshingOptions::regionMayShrink, it collapsed nothing and came back with
// every vertex). About a sixteenth of the moving vertices remain (within a factor 2), every fixed
// vertex stays where it was (its index may change), and the coarse start counts one level (the grid's 11,200 moving vertices at its mean face: above
// 4 × 2,500) and coarsens by 2 (all faces have one area).
TEST(CoarseStart, ABorderedMeshRemeshesCoarseAroundItsFixedRows) {
  const TriMesh grid = shapes::grid(110, 110);
  MovingRegion region(grid, {}, BoundaryMode::Fixed);
  const int moving = region.roles().freeCount;
  const CoarseStart start = coarseStart(region);
  EXPECT_EQ(start.levels, 1);
  EXPECT_NEAR(start.coarsening, 2, 1e-9);
  EXPECT_TRUE(start.onMovingFaces);
  const std::vector<std::uint8_t> fixed = [&] {
    std::vector<std::uint8_t> f(grid.vertexCount());
    for (int v = 0; v < grid.vertexCount(); ++v) f[v] = !region.roles().free[v];
    return f;
  }();
  ASSERT_TRUE(remeshMovingRegion(region, false, 4));
  const int after = region.roles().freeCount;
  EXPECT_LT(after, moving / 8);
  EXPECT_GT(after, moving / 32);
  EXPECT_TRUE(test::keepsPositions(grid, fixed, region.mesh()));
  EXPECT_FALSE(selfIntersects(region.mesh()));
}

// The 20° rule on a whole mesh with a border counts the faces a remeshing can reshape: a 10×10
// unit grid (two fixed rows around its border) with one moving vertex pushed 0.8 along x toward
// its neighbour has thin moving faces (smallest angle measured 6.3° and 11.3°). Pushed next to the
// fixed rows (vertex (2, 5)), those faces have a vertex beside a fixed one, whose edges the
// remeshing keeps: no remeshing is asked for. Pushed inside (vertex (5, 5)), one is.
// A selection (every face selected) counts every moving face, as before.
TEST(NeedsRemeshing, AWholeMeshWithABorderIgnoresFacesBesideItsFixedRows) {
  const auto pushed = [](int i, int j) {
    TriMesh grid = shapes::grid(10, 10);
    grid.positions[j * 11 + i].x() += 0.8;
    return grid;
  };
  const MovingRegion besideFixed(pushed(2, 5), {}, BoundaryMode::Fixed);
  ASSERT_LT(smallestMovingAngle(besideFixed), 20);
  EXPECT_FALSE(needsRemeshing(besideFixed));
  const MovingRegion inside(pushed(5, 5), {}, BoundaryMode::Fixed);
  ASSERT_LT(smallestMovingAngle(inside), 20);
  EXPECT_TRUE(needsRemeshing(inside));
  const TriMesh selected = pushed(2, 5);
  const MovingRegion selection(selected, std::vector<std::uint8_t>(selected.faces.size(), 1), BoundaryMode::Fixed);
  ASSERT_LT(smallestMovingAngle(selection), 20);
  EXPECT_TRUE(needsRemeshing(selection));
}

// A run's wall-time limit reaches its remeshings (MovingRegion::deadline): with the limit passed,
// the isotropic, the curvature-adaptive, the split and the on-surface remeshing are each refused
// and the region stays bit for bit; without one, the same calls remesh. (A past deadline, so no
// clock is read against a duration: the outcome does not depend on the machine's speed.)
TEST(RemeshingDeadline, ARemeshingAfterTheRunsLimitIsRefusedAndTheRegionKept) {
  const TriMesh thin = shapes::torus(8, 1, 48, 8);
  auto unlimited = [&] { return MovingRegion(thin, {}, BoundaryMode::Fixed); };
  {  // without a deadline, each call remeshes
    MovingRegion a = unlimited(), b = unlimited(), c = unlimited(), d = unlimited();
    ASSERT_TRUE(remeshMovingRegion(a, true));
    ASSERT_TRUE(remeshMovingRegion(b, false));
    ASSERT_TRUE(splitLongEdges(c));
    ASSERT_TRUE(remeshOnSurface(d, 0.5));
  }
  MovingRegion late(thin, {}, BoundaryMode::Fixed);
  late.setDeadline(std::chrono::steady_clock::now());
  EXPECT_FALSE(remeshMovingRegion(late, true));
  EXPECT_FALSE(remeshMovingRegion(late, false));
  EXPECT_FALSE(splitLongEdges(late));
  EXPECT_FALSE(remeshOnSurface(late, 0.5));
  EXPECT_EQ(late.mesh().positions, thin.positions);
  EXPECT_EQ(late.mesh().faces, thin.faces);
  MovingRegion copy = late.copyTakingCaches();  // a stage's copy keeps the run's limit
  EXPECT_EQ(copy.deadline(), late.deadline());
}
