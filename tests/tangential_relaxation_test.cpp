// SPDX-License-Identifier: GPL-3.0-or-later
// Tangential relaxation and untangling (mesh/tangential_relaxation.h): the moves stay in the
// surface, a jittered mesh comes out untangled, and the tangle test tells a jittered mesh from a
// clean one.
#include "test_meshes.h"

#include <elastica/mesh_quality.h>
#include <elastica/shapes.h>
#include "mesh/tangential_relaxation.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace elastica;

namespace {

// A 20×20 unit grid with every interior vertex jittered within the plane by up to `amount` per axis.
TriMesh jitteredGrid(double amount, std::vector<std::uint8_t>& interior) {
  TriMesh m = shapes::grid(20, 20);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-amount, amount);
  interior.assign(m.vertexCount(), 0);
  for (int v = 0; v < m.vertexCount(); ++v) {
    const Vec3 p = m.positions[v];
    if (p.x() > 0 && p.x() < 20 && p.y() > 0 && p.y() < 20) {
      interior[v] = 1;
      m.positions[v] += Vec3(u(rng), u(rng), 0);
    }
  }
  return m;
}

}  // namespace

// In a plane the tangent plane is the plane: the vertices stay in it to rounding, the border does
// not move, and jitter of 0.45 cell per axis (faces folded over) is undone: no fold, and the
// smallest angle comes back above 20° (the grid's own is 45°).
TEST(Untangle, UnfoldsAJitteredGridWithinItsPlane) {
  std::vector<std::uint8_t> interior;
  TriMesh m = jitteredGrid(0.45, interior);
  const TriMesh before = m;
  ASSERT_TRUE(isTangled(m, {}, 1.0));
  const int passes = untangle(m, interior, {});
  EXPECT_GT(passes, 0);
  EXPECT_FALSE(isTangled(m, {}, 1.0));
  EXPECT_GT(smallestAngleDegrees(m), 20.0);
  for (int v = 0; v < m.vertexCount(); ++v) {
    EXPECT_NEAR(m.positions[v].z(), 0.0, 1e-12);
    if (!interior[v]) {
      EXPECT_EQ(m.positions[v], before.positions[v]);
    }
  }
}

// A clean icosphere is not tangled; one face turned over (its corners' order reversed) is a fold.
TEST(Untangle, TangleTestFindsAFoldAndPassesACleanMesh) {
  TriMesh m = shapes::icosphere(1, 3);
  EXPECT_FALSE(isTangled(m, {}, 1.0));
  std::swap(m.faces[5][1], m.faces[5][2]);
  EXPECT_TRUE(isTangled(m, {}, 1.0));
  std::vector<std::uint8_t> others(m.faces.size(), 1);
  others[5] = 0;  // only the flagged faces count
  EXPECT_FALSE(isTangled(m, others, 1.0));
}
