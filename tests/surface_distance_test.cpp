// SPDX-License-Identifier: GPL-3.0-or-later
// The restoration benchmark's sampled distance (tests/support/surface_distance.h) against
// analytic distances, and its nearest-face search against brute force, near and far.
#include "surface_distance.h"

#include <elastica/shapes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace elastica;

namespace {

TriMesh moved(TriMesh m, const Vec3& by) {
  for (Vec3& p : m.positions) p += by;
  return m;
}

// A single point as a (degenerate) mesh: its samples all sit at p, so the distance is p's.
TriMesh pointMesh(const Vec3& p) { return {{p, p, p}, {{0, 1, 2}}}; }

}  // namespace

TEST(SurfaceDistance, ParallelPlanesAreTheirSpacingApart) {
  // Every sample of the small square lies straight above the large one, 0.37 away.
  const TriMesh a = moved(shapes::grid(10, 10, 0.1), Vec3(0.5, 0.5, 0.37)), b = shapes::grid(20, 20, 0.1);
  const bench::DistanceStats d = bench::sampledDistance(a, b, 4);
  EXPECT_NEAR(d.rms, 0.37, 1e-12);
  EXPECT_NEAR(d.max, 0.37, 1e-12);
}

TEST(SurfaceDistance, ConcentricSpheresAreTheirRadiiApart) {
  // Level-3 icospheres lie between their circumscribed sphere and one 0.5% smaller, so every
  // distance is 2 within 0.02 — either way round, though from the big sphere every point is far
  // from the small one (the case a uniform grid searched slowly).
  const TriMesh small = shapes::icosphere(1, 3), big = shapes::icosphere(3, 3);
  for (const auto& d : {bench::sampledDistance(small, big), bench::sampledDistance(big, small)}) {
    EXPECT_NEAR(d.rms, 2, 0.02);
    EXPECT_NEAR(d.max, 2, 0.02);
  }
}

TEST(SurfaceDistance, NearestFaceIsBruteForcesNearestFace) {
  // A bumpy sphere, and points inside it, on it, and up to 100 radii away: the tree's answer is
  // the smallest of the distances to each face alone (the same arithmetic, so equal exactly).
  TriMesh b = shapes::icosphere(1, 2);
  shapes::addRadialNoise(b, 0.2, 7);
  std::mt19937 random(11);
  std::normal_distribution<double> gauss;
  for (double radius : {0.0, 0.5, 1.0, 1.5, 10.0, 100.0}) {
    for (int k = 0; k < 6; ++k) {
      const Vec3 p = radius * Vec3(gauss(random), gauss(random), gauss(random)).normalized();
      double brute = std::numeric_limits<double>::infinity();
      for (const Face& f : b.faces) {
        const TriMesh one{{b.positions[f[0]], b.positions[f[1]], b.positions[f[2]]}, {{0, 1, 2}}};
        brute = std::min(brute, bench::sampledDistance(pointMesh(p), one, 1).max);
      }
      EXPECT_EQ(bench::sampledDistance(pointMesh(p), b, 1).max, brute) << "at " << p.transpose();
    }
  }
}
