// SPDX-License-Identifier: GPL-3.0-or-later
// A region's resolution (flow/region_resolution.h): a region that resolves its surface keeps its
// energy under one Loop subdivision of the region; a faceted one (flat faces meeting at a crease,
// the vector scheme's lid on a clamped region) does not.
#include "flow/region_resolution.h"
#include "flow/resolution_check.h"

#include <elastica/shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace elastica {
namespace {

// Every face of a closed sphere as the region: every vertex is inner, and (4H² − 2K) A sums to
// 8π (DESIGN.md: the mixed-area energy of a level-4 icosphere is within 0.1 % of it).
TEST(RegionResolution, AWholeSphereIsResolvedAtItsEnergy) {
  const TriMesh sphere = shapes::icosphere(1, 4);
  const RegionResolution r = measureRegionResolution(sphere, std::vector<std::uint8_t>(sphere.faceCount(), 1), {});
  EXPECT_NEAR(r.energy, 8 * M_PI, 0.005 * 8 * M_PI);
  EXPECT_NEAR(r.loopEnergy, 8 * M_PI, 0.005 * 8 * M_PI);
  EXPECT_TRUE(r.resolved()) << r.gap();
}

// A cap of the sphere (its faces above z = 0.3): its inner vertices and their part of the
// subdivided cap cost nearly the same; Loop pulls the cap in against its rim, which stays, by the
// square of the edge length (measured: +2.4 %), far below a faceted region's rise.
TEST(RegionResolution, ASphereCapIsResolved) {
  const TriMesh sphere = shapes::icosphere(1, 4);
  std::vector<std::uint8_t> cap(sphere.faceCount(), 0);
  for (int f = 0; f < sphere.faceCount(); ++f) {
    double z = 0;
    for (int v : sphere.faces[f]) z += sphere.positions[v].z() / 3;
    cap[f] = z > 0.3;
  }
  const RegionResolution r = measureRegionResolution(sphere, cap, {});
  EXPECT_GT(r.energy, 1);
  EXPECT_LT(std::abs(r.gap()), 0.04) << r.energy << " " << r.loopEnergy;
  EXPECT_TRUE(r.resolved());
}

// A flat region costs nothing at either resolution.
TEST(RegionResolution, AFlatRegionCostsNothing) {
  const TriMesh plane = shapes::grid(12, 12, 0.5);
  const RegionResolution r = measureRegionResolution(plane, std::vector<std::uint8_t>(plane.faceCount(), 1), {});
  EXPECT_NEAR(r.energy, 0, 1e-9);
  EXPECT_NEAR(r.loopEnergy, 0, 1e-9);
  EXPECT_TRUE(r.resolved());
}

// A closed mesh with every face in the region is measured as the whole-mesh check measures it
// (resolution_check.h, the same Loop masks): a torus of R/r 3 with 5 edges around its tube, whose
// coarse energy is far from its surface's, is not resolved by either.
TEST(RegionResolution, AClosedMeshIsMeasuredAsTheWholeMeshCheckMeasuresIt) {
  const TriMesh tube = shapes::torus(3, 1, 48, 5);
  Resolution whole;
  ASSERT_TRUE(measureResolution(tube, {}, whole));
  const RegionResolution r = measureRegionResolution(tube, std::vector<std::uint8_t>(tube.faceCount(), 1), {});
  EXPECT_NEAR(r.energy, whole.energy, 1e-9 * std::abs(whole.energy));
  EXPECT_NEAR(r.loopEnergy, whole.loopEnergy, 1e-9 * std::abs(whole.loopEnergy));
  EXPECT_GT(r.gap(), kRegionResolvedGap);
  EXPECT_FALSE(r.resolved()) << r.gap();
  EXPECT_EQ(r.resolvedEnergy(), std::max(r.energy, r.loopEnergy));
}

}  // namespace
}  // namespace elastica
