// SPDX-License-Identifier: GPL-3.0-or-later
// The kept crossing test (mesh/crossing_cache.h) gives the plain test's answers
// (mesh/self_intersection.h) on a mesh whose faces move between calls, and builds its grid again
// exactly when a face it keeps changes.
#include <elastica/shapes.h>
#include "mesh/crossing_cache.h"
#include "mesh/self_intersection.h"

#include <gtest/gtest.h>

#include <random>

using namespace elastica;

namespace {

// Two icospheres of radius 1 whose centres are 1.6 apart: their faces cross along a circle.
TriMesh overlappingSpheres() {
  const TriMesh sphere = shapes::icosphere(1, 3);
  TriMesh m = sphere;
  for (const Vec3& p : sphere.positions) m.positions.push_back(p + Vec3(1.6, 0, 0));
  for (const Face& f : sphere.faces) m.faces.push_back({f[0] + sphere.vertexCount(), f[1] + sphere.vertexCount(), f[2] + sphere.vertexCount()});
  return m;
}

// Faces with every corner among `movable` (the flow's active faces).
std::vector<std::uint8_t> facesOf(const TriMesh& m, const std::vector<std::uint8_t>& movable) {
  std::vector<std::uint8_t> flagged(m.faces.size(), 0);
  for (std::size_t f = 0; f < m.faces.size(); ++f) flagged[f] = movable[m.faces[f][0]] || movable[m.faces[f][1]] || movable[m.faces[f][2]];
  return flagged;
}

}  // namespace

TEST(CrossingCache, GivesThePlainTestsAnswersOnAMovingMesh) {
  TriMesh m = overlappingSpheres();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.08, 0.08);
  // The first sphere's vertices with x > 0.3 move (the part that meets the second sphere, and more).
  std::vector<std::uint8_t> movable(m.positions.size(), 0);
  for (int v = 0; v < m.vertexCount() / 2; ++v) movable[v] = m.positions[v].x() > 0.3;
  const std::vector<std::uint8_t> moving = facesOf(m, movable);
  CrossingCache cache;
  int roundsWithCrossings = 0, expectedBuilds = 0;
  for (int round = 0; round < 12; ++round) {
    for (int v = 0; v < m.vertexCount(); ++v)
      if (movable[v]) m.positions[v] += Vec3(jitter(rng), jitter(rng), jitter(rng));
    if (round % 4 == 3) {  // the kept sphere moves into the other: the cache must notice
      for (int v = m.vertexCount() / 2; v < m.vertexCount(); ++v) m.positions[v].x() -= 0.15;
      ++expectedBuilds;
    }
    if (round == 0) ++expectedBuilds;
    const std::vector<int> plain = selfIntersectingFaces(m, &moving);
    EXPECT_EQ(cache.crossingFaces(m, moving), plain) << round;
    EXPECT_EQ(cache.crosses(m, moving), selfIntersects(m, &moving)) << round;
    roundsWithCrossings += !plain.empty();
  }
  EXPECT_EQ(roundsWithCrossings, 12);
  EXPECT_EQ(cache.builds(), expectedBuilds);
}

TEST(CrossingCache, BuildsAgainWhenAKeptFaceIsRewrittenOrTheFlagsChange) {
  TriMesh m = overlappingSpheres();
  std::vector<std::uint8_t> movable(m.positions.size(), 0);
  for (int v = 0; v < m.vertexCount() / 2; ++v) movable[v] = 1;  // the first sphere moves, the second is kept
  std::vector<std::uint8_t> moving = facesOf(m, movable);
  CrossingCache cache;
  EXPECT_EQ(cache.crossingFaces(m, moving), selfIntersectingFaces(m, &moving));
  // Shift the first sphere away: no crossing left, and the kept grid is reused.
  for (int v = 0; v < m.vertexCount() / 2; ++v) m.positions[v].x() -= 3;
  EXPECT_FALSE(cache.crosses(m, moving));
  EXPECT_EQ(cache.builds(), 1);
  // A kept face rewritten in place (its corners moved into the first sphere's place) crosses it.
  const int kept = static_cast<int>(m.faces.size()) - 1;
  m.faces[kept] = {0, 1, m.vertexCount() - 1};
  EXPECT_EQ(cache.crossingFaces(m, moving), selfIntersectingFaces(m, &moving));
  EXPECT_EQ(cache.builds(), 2);
  // Other flags: the plain test's answer for them.
  moving.assign(m.faces.size(), 0);
  moving[kept] = 1;
  EXPECT_EQ(cache.crosses(m, moving), selfIntersects(m, &moving));
  EXPECT_EQ(cache.builds(), 3);
}
