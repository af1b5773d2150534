// SPDX-License-Identifier: GPL-3.0-or-later
// The bi-Laplace start of a hole's patch (restoration/biharmonic_embedding): free vertices solve
// (C M⁻¹ C) x = 0 with every other vertex fixed.
#include "exact_compare.h"
#include <elastica/shapes.h>
#include "restoration/biharmonic_embedding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace elastica;

namespace {

constexpr int kN = 12;  // a 12×12 grid of unit squares

// Free: the 7×7 vertices with 3 ≤ i, j ≤ 9, three rings from the grid's boundary (the solve needs
// two: a free vertex's Δ² stencil must be complete).
std::vector<std::uint8_t> centreBlock(const TriMesh& m) {
  std::vector<std::uint8_t> free(m.positions.size(), 0);
  for (int v = 0; v < m.vertexCount(); ++v) {
    const int i = v % (kN + 1), j = v / (kN + 1);
    free[v] = i >= 3 && i <= 9 && j >= 3 && j <= 9;
  }
  return free;
}

}  // namespace

// Affine precision: the rows of C M⁻¹ C sum to zero, so when every fixed vertex lies on a plane the
// solution does too, from any start and in any iteration. A grid tilted onto a general plane, its
// free vertices thrown off it by up to 0.4 along each axis, is solved back onto the plane to 1e-10
// (the grid is 12 edges wide); fixed vertices stay bit for bit.
TEST(BiharmonicEmbedding, ReproducesAPlane) {
  TriMesh m = shapes::grid(kN, kN, 1.0);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
  const Vec3 origin(0.5, -2, 3);
  for (Vec3& p : m.positions) p = R * p + origin;
  const Vec3 normal = R * Vec3(0, 0, 1);
  const std::vector<std::uint8_t> free = centreBlock(m);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  for (int v = 0; v < m.vertexCount(); ++v)
    if (free[v]) m.positions[v] += Vec3(u(rng), u(rng), u(rng));
  const TriMesh before = m;

  solveBiharmonic(m, free);
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (free[v]) EXPECT_NEAR(normal.dot(m.positions[v] - origin), 0, 1e-10) << "vertex " << v;
    else EXPECT_TRUE(test::bitEqual(m.positions[v], before.positions[v])) << "vertex " << v;
  }
}

// Quadratic precision where the discrete operator has it: on a flat regular grid C is the 5-point
// stencil (the diagonals' opposite angles are right angles, cot = 0) and every interior vertex's
// mixed area is one square, so M⁻¹C q is constant for a quadratic q(x, y) and Δ²q = 0 at vertices
// whose 2-ring is interior. A height field z = ε q(x, y) on the fixed vertices bends the mesh out of
// the plane, which changes lengths and angles, hence the weights, only at O(ε²): one solve puts the
// free vertices within O(ε³) of the quadratic (measured in z at the vertex's own x, y). Halving ε
// from 0.02 to 0.0025 must divide that error by at least 6 each time (8 in the limit).
TEST(BiharmonicEmbedding, ReproducesAQuadraticHeightToThirdOrder) {
  auto error = [](double eps) {
    TriMesh m = shapes::grid(kN, kN, 1.0);
    const std::vector<std::uint8_t> free = centreBlock(m);
    auto q = [eps](const Vec3& p) {
      const double x = p.x() - 6, y = p.y() - 6;
      return eps * (x * x + 0.5 * x * y - 0.75 * y * y);
    };
    for (int v = 0; v < m.vertexCount(); ++v)
      if (!free[v]) m.positions[v].z() = q(m.positions[v]);
    solveBiharmonic(m, free, 1);
    double worst = 0;
    for (int v = 0; v < m.vertexCount(); ++v)
      if (free[v]) worst = std::max(worst, std::abs(m.positions[v].z() - q(m.positions[v])));
    return worst;
  };
  double previous = error(0.02);
  for (double eps : {0.01, 0.005, 0.0025}) {
    const double e = error(eps);
    EXPECT_GT(previous / e, 6) << eps;
    previous = e;
  }
}
