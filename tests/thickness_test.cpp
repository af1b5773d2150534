// SPDX-License-Identifier: GPL-3.0-or-later
// The local thickness of closed parts (mesh/thickness.h) on shapes whose thickness is known: a
// thin slab, a torus of tube radius r (2r), a sphere (its diameter); and the CAD working edge
// length it sizes (flow/mesh_quality_stage.h: cadWorkingEdgeLength).
#include <elastica/shapes.h>
#include "flow/mesh_quality_stage.h"
#include "flow/moving_region.h"
#include "mesh/thickness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

using namespace elastica;

namespace {

// A slab of n × n unit voxels one voxel thick, its z scaled by `thickness`.
TriMesh slab(int n, double thickness) {
  std::vector<std::array<int, 3>> cells;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) cells.push_back({i, j, 0});
  TriMesh mesh = shapes::voxelSurface(cells);
  for (Vec3& p : mesh.positions) p.z() *= thickness;
  return mesh;
}

void reverseFaces(TriMesh& mesh) {
  for (Face& f : mesh.faces) std::swap(f[1], f[2]);
}

}  // namespace

TEST(Thickness, ThinSlabIsItsThicknessOnItsLargeSides) {
  const double t = 0.1;
  const TriMesh mesh = slab(10, t);
  const std::vector<double> thickness = faceThickness(mesh);
  int large = 0;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Face& face = mesh.faces[f];
    const Vec3 n = (mesh.positions[face[1]] - mesh.positions[face[0]]).cross(mesh.positions[face[2]] - mesh.positions[face[0]]);
    if (std::abs(n.normalized().z()) > 0.5) {  // the top and the bottom: straight across
      ++large;
      if (std::isfinite(thickness[f])) {
        EXPECT_NEAR(thickness[f], t, 1e-12);
      }
    } else if (std::isfinite(thickness[f])) {  // a rim face: across the slab's width, 10
      EXPECT_NEAR(thickness[f], 10, 1e-9);
    }
  }
  EXPECT_EQ(large, 2 * 4 * 10 * 10);  // four triangles a square, top and bottom
  // The rim is 4 % of the area: a low quantile is the slab's thickness, the highest its width.
  EXPECT_NEAR(thinnestFeature(mesh, 0.1), t, 1e-12);
  EXPECT_NEAR(thinnestFeature(mesh, 1.0), 10, 1e-9);
}

TEST(Thickness, TorusIsTwiceItsTubeRadius) {
  const double R = 1, r = 0.2;
  const TriMesh mesh = shapes::torus(R, r, 96, 48);
  const std::vector<double> thickness = faceThickness(mesh);
  // A face's centroid lies inside the tube by up to r(1 − cos(π/48)) and its normal is the
  // facet's: within 1 % of 2r.
  int finite = 0;
  for (double t : thickness)
    if (std::isfinite(t)) {
      ++finite;
      EXPECT_NEAR(t, 2 * r, 0.01 * 2 * r);
    }
  EXPECT_GE(finite, mesh.faceCount() * 99 / 100);
  EXPECT_NEAR(thinnestFeature(mesh, 0.1), 2 * r, 0.01 * 2 * r);
}

TEST(Thickness, SphereIsItsDiameterWhicheverWayItsFacesTurn) {
  const double R = 2;
  TriMesh mesh = shapes::icosphere(R, 4);
  const double outward = thinnestFeature(mesh, 0.1);
  EXPECT_NEAR(outward, 2 * R, 0.005 * 2 * R);
  for (double t : faceThickness(mesh)) EXPECT_NEAR(t, 2 * R, 0.005 * 2 * R);
  reverseFaces(mesh);
  EXPECT_EQ(thinnestFeature(mesh, 0.1), outward);  // the inward normal is found from the volume's sign
}

TEST(Thickness, AnOpenSheetHasNone) {
  const TriMesh sheet = shapes::grid(8, 8);
  for (double t : faceThickness(sheet)) EXPECT_EQ(t, std::numeric_limits<double>::infinity());
  EXPECT_EQ(thinnestFeature(sheet, 0.1), 0);
}

// The CAD working edge: three edges across the thinnest feature, unless the vertex budget of the
// part's genus asks for longer edges; none on a sheet with a boundary.
TEST(Thickness, CadWorkingEdgeIsAThirdOfTheThinnestFeatureWithinTheBudget) {
  const double r = 0.2;
  MovingRegion ring(shapes::torus(1, r, 96, 48), {}, BoundaryMode::Fixed);
  const double edge = cadWorkingEdgeLength(ring);
  // The budget's floor on this torus (area 4π²Rr ≈ 7.9): about 0.04, below 2r/3 = 0.133.
  EXPECT_NEAR(edge, thinnestFeature(ring.mesh(), 0.1) / 3, 1e-15);

  // A 40 × 40 slab of thickness 0.01: a third of it would need about 2 × 3,200 / (√3 · 0.0033²)
  // ≈ 3.4e8 vertices, far above the budget, so the edge is the budget's: the remeshing of its area
  // into vertexBudget(moving, 0) equilateral vertices.
  MovingRegion thin(slab(40, 0.01), {}, BoundaryMode::Fixed);
  const double area = 2 * 40 * 40 + 4 * 40 * 0.01;
  const double budget = static_cast<double>(vertexBudget(thin.roles().freeCount, 0));
  EXPECT_NEAR(cadWorkingEdgeLength(thin), std::sqrt(2 * area / (std::sqrt(3.0) * budget)), 1e-12);

  MovingRegion sheet(shapes::grid(8, 8), {}, BoundaryMode::Fixed);
  EXPECT_EQ(cadWorkingEdgeLength(sheet), 0);
}
