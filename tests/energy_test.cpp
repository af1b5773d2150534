// SPDX-License-Identifier: GPL-3.0-or-later
#include "test_meshes.h"

#include <elastica/energy.h>
#include <elastica/shapes.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace elastica;

namespace {

double energyOf(const TriMesh& m, const std::vector<std::uint8_t>* active = nullptr) {
  const Topology t(m.vertexCount(), m.faces);
  const Geometry g = computeGeometry(t, m.positions);
  const Curvature c = computeCurvature(t, g, m.positions);
  return totalCurvatureEnergy(t, g, c, active);
}

// E of a torus of revolution with a = R/r: 4W with W = π² a²/√(a² − 1).
double torusEnergy(double R, double r) {
  const double a = R / r;
  return 4 * M_PI * M_PI * a * a / std::sqrt(a * a - 1);
}

}  // namespace

// E = ∫(k1² + k2²) = 8π for every round sphere, whatever its radius.
TEST(Energy, SphereIsEightPi) {
  for (double r : {0.5, 2.0, 7.0}) EXPECT_NEAR(energyOf(shapes::icosphere(r, 5)), 8 * M_PI, 0.01 * 8 * M_PI) << r;
}

TEST(Energy, TorusOfRevolution) {
  EXPECT_NEAR(energyOf(shapes::torus(3, 1, 96, 32)), torusEnergy(3, 1), 0.02 * torusEnergy(3, 1));
  // The Clifford torus a = √2 minimises E among tori: 8π².
  const double clifford = 8 * M_PI * M_PI;
  EXPECT_NEAR(torusEnergy(std::sqrt(2.0), 1), clifford, 1e-12);
  EXPECT_NEAR(energyOf(shapes::torus(std::sqrt(2.0), 1, 72, 36)), clifford, 0.02 * clifford);
}

TEST(Energy, FlatGridIsZero) { EXPECT_NEAR(energyOf(shapes::grid(9, 9)), 0.0, 1e-12); }

// An active mask restricts the sum; the two halves of a sphere add up to the whole.
TEST(Energy, ActiveMaskSplitsTheSum) {
  const TriMesh m = shapes::icosphere(1.0, 3);
  std::vector<std::uint8_t> upper(m.vertexCount()), lower(m.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) upper[v] = !(lower[v] = m.positions[v].z() < 0);
  EXPECT_NEAR(energyOf(m, &upper) + energyOf(m, &lower), energyOf(m), 1e-9);
  EXPECT_GT(energyOf(m, &upper), 0.3 * energyOf(m));
}

// Noise raises the energy above the sphere's minimum 8π (Willmore: spheres minimise W).
TEST(Energy, NoiseRaisesTheEnergy) {
  EXPECT_GT(energyOf(test::jittered(shapes::icosphere(1.0, 3), 0.02)), 1.2 * 8 * M_PI);
}
