// SPDX-License-Identifier: GPL-3.0-or-later
// A CAD tessellation remeshed on its own surface (mesh/surface_projection.h,
// PatchRemeshingOptions::surface, flow/mesh_quality_stage.h: remeshOnSurface): its sharp edges
// found, closest points on the sheet turned the vertex's way, and a remeshing that moves the
// triangulation, not the part.
#include "cad_parts.h"
#include "flow/mesh_quality_stage.h"
#include "flow/moving_region.h"
#include "mesh/self_intersection.h"
#include "mesh/surface_projection.h"
#include "surface_distance.h"

#include <elastica/mesh_quality.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace elastica;

namespace {

// The vertices of `m` as a mesh of point faces (v, v, v): bench::sampledDistance of it is the
// distance of the vertices themselves.
TriMesh verticesOf(const TriMesh& m) {
  TriMesh points;
  points.positions = m.positions;
  for (int v = 0; v < m.vertexCount(); ++v) points.faces.push_back({v, v, v});
  return points;
}

double sharpLength(const TriMesh& m) {
  double length = 0;
  for (const auto& [a, b] : sharpEdges(m, 60)) length += (m.positions[a] - m.positions[b]).norm();
  return length;
}

}  // namespace

// A washer drawn with slivers (60 segments): its sharp edges are the four rims, 240 edges, each
// between neighbours on one circle; the 6° between neighbouring facets are not sharp.
TEST(SurfaceProjection, SharpEdgesOfACadRingAreItsFourRims) {
  const TriMesh ring = test::cadRing(60, 1, 0.6, 0.1);
  const auto sharp = sharpEdges(ring, 60);
  ASSERT_EQ(sharp.size(), 240u);
  for (const auto& [a, b] : sharp) {
    EXPECT_EQ(a / 60, b / 60) << a << " " << b;  // one circle
    EXPECT_TRUE(b - a == 1 || b - a == 59) << a << " " << b;
  }
}

// Between the two walls of a thin tube (1 % of the radius), the closest point is on the wall the
// normal faces: outward onto the outer wall, inward onto the inner one, whichever is nearer.
TEST(SurfaceProjection, ProjectsOntoTheSheetTurnedTheNormalsWay) {
  const TriMesh tube = test::cadRing(150, 0.5, 0.495, 0.225);
  const SurfaceProjector surface(tube, 60);
  const Vec3 between(0, 0, 0.496);  // nearer the inner wall (0.495)
  Vec3 out, in, any;
  ASSERT_TRUE(surface.project(between, Vec3(0, 0, 1), out));
  ASSERT_TRUE(surface.project(between, Vec3(0, 0, -1), in));
  ASSERT_TRUE(surface.project(between, Vec3::Zero(), any));
  // The facets' chords lie inside the circles: the outer wall at z = 0.5 cos(π/150), the inner
  // one at 0.495 cos(π/150).
  const double chord = std::cos(M_PI / 150);
  EXPECT_NEAR(out.z(), 0.5 * chord, 1e-9);
  EXPECT_NEAR(in.z(), 0.495 * chord, 1e-9);
  EXPECT_NEAR(any.z(), 0.495 * chord, 1e-9);
  Vec3 rim;
  ASSERT_TRUE(surface.projectOnSharpEdge(Vec3(0.3, 0, 0.4), rim));
  EXPECT_NEAR(rim.x(), 0.225, 1e-12);
}

// A washer of slivers (60 segments, corners down to 8.8°) remeshed on its surface toward edges of
// 0.05: every vertex lies on the input's faces (within 1e-9 of the 2-wide part), the sharp rims are
// still sharp edges, on the input's rims and as long within 1 %, the triangles are fit for the
// flow (smallest corner above 15°; measured 16.5°), and no face crosses. Without the surface, the relaxation
// carries the vertices off the facets and across the rims.
TEST(SurfaceProjection, RemeshingOnTheSurfaceMovesTheTriangulationNotThePart) {
  const TriMesh washer = test::cadRing(60, 1, 0.6, 0.1);
  ASSERT_LT(smallestAngleDegrees(washer, std::vector<std::uint8_t>(washer.faces.size(), 1)), 10);
  MovingRegion region(washer, {}, BoundaryMode::Fixed);
  ASSERT_TRUE(remeshOnSurface(region, 0.05));
  const TriMesh& m = region.mesh();
  EXPECT_GT(m.vertexCount(), 4 * washer.vertexCount());
  EXPECT_LT(bench::sampledDistance(verticesOf(m), washer, 1).max, 1e-9);
  const SurfaceProjector rims(washer, 60);
  for (const auto& [a, b] : sharpEdges(m, 60))
    for (int v : {a, b}) {
      Vec3 onRim;
      ASSERT_TRUE(rims.projectOnSharpEdge(m.positions[v], onRim));
      EXPECT_LT((onRim - m.positions[v]).norm(), 1e-9) << v;
    }
  EXPECT_NEAR(sharpLength(m), sharpLength(washer), 0.01 * sharpLength(washer));
  EXPECT_GT(smallestAngleDegrees(m, std::vector<std::uint8_t>(m.faces.size(), 1)), 15);
  EXPECT_FALSE(selfIntersects(m));
  EXPECT_EQ(closedGenus(region.topology()), 1);
}
