// SPDX-License-Identifier: GPL-3.0-or-later
// Sliding boundaries (flow/boundary_slide, BoundaryMode::Slide): boundary vertices move along the
// boundary polylines recorded at the start, towards even spacing; corners stay; nothing else moves.
#include "exact_compare.h"
#include <elastica/shapes.h>
#include <elastica/topology.h>
#include "flow/boundary_slide.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace elastica;

namespace {

constexpr int kN = 8;  // an 8×8 grid of unit squares: the boundary is the square [0, 8]²

bool onSide(const Vec3& p) { return p.x() == 0 || p.x() == kN || p.y() == 0 || p.y() == kN; }
bool isCorner(const Vec3& p) { return (p.x() == 0 || p.x() == kN) && (p.y() == 0 || p.y() == kN); }

// Largest deviation from 1 of the distance between consecutive boundary vertices.
double worstGap(const Topology& topo, const std::vector<Vec3>& p) {
  double worst = 0;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    if (!topo.isBoundaryEdge(e)) continue;
    const auto& ev = topo.edgeVertices(e);
    worst = std::max(worst, std::abs((p[ev[0]] - p[ev[1]]).norm() - 1));
  }
  return worst;
}

}  // namespace

// Boundary vertices shifted unevenly along their sides slide back to even spacing: every pass
// keeps them exactly on their side (the side's coordinate unchanged to 1e-12, z = 0) and does not
// worsen the spacing; 1,000 passes at rate ½ even it out to 1e-9 of an edge (the slowest mode of an
// 8-edge side decays by 1 − ½(1 − cos π/8) ≈ 0.962 a pass). Corners and interior vertices do not move.
TEST(BoundarySlide, EvensOutSpacingAlongTheSides) {
  const TriMesh grid = shapes::grid(kN, kN, 1.0);
  const Topology topo(grid.vertexCount(), grid.faces);
  BoundarySlider slider(topo, grid.positions);

  std::vector<Vec3> p = grid.positions;
  std::vector<std::uint8_t> sliding(p.size(), 0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (std::size_t v = 0; v < p.size(); ++v) {
    if (!onSide(p[v])) continue;
    sliding[v] = 1;
    if (isCorner(p[v])) continue;
    if (p[v].x() == 0 || p[v].x() == kN) p[v].y() += u(rng);  // along its side
    else p[v].x() += u(rng);
  }
  const std::vector<Vec3> start = p;
  slider.attach(topo, p, sliding);
  double gap = worstGap(topo, p);
  ASSERT_GT(gap, 0.2);
  for (int pass = 0; pass < 1000; ++pass) {
    slider.slide(topo, p, sliding, 0.5);
    const double g = worstGap(topo, p);
    ASSERT_LE(g, gap + 1e-12) << "pass " << pass;
    gap = g;
  }
  EXPECT_LT(gap, 1e-9);
  for (std::size_t v = 0; v < p.size(); ++v) {
    const Vec3& p0 = grid.positions[v];
    if (!sliding[v] || isCorner(p0)) {
      EXPECT_TRUE(test::bitEqual(p[v], start[v])) << "vertex " << v;
      continue;
    }
    if (p0.x() == 0 || p0.x() == kN) EXPECT_NEAR(p[v].x(), p0.x(), 1e-12) << v;
    else EXPECT_NEAR(p[v].y(), p0.y(), 1e-12) << v;
    EXPECT_EQ(p[v].z(), 0.0) << v;
  }
}

// A sliding vertex pushed off the boundary (out of the plane and outwards) is projected back onto
// the recorded polyline, to its nearest point (rate 0: projection only), to 1e-12.
TEST(BoundarySlide, ProjectsOntoTheRecordedPolyline) {
  const TriMesh grid = shapes::grid(kN, kN, 1.0);
  const Topology topo(grid.vertexCount(), grid.faces);
  BoundarySlider slider(topo, grid.positions);
  std::vector<std::uint8_t> sliding(grid.positions.size(), 0);
  for (std::size_t v = 0; v < sliding.size(); ++v) sliding[v] = onSide(grid.positions[v]);
  std::vector<Vec3> p = grid.positions;
  slider.attach(topo, p, sliding);
  const int v = 3;  // (3, 0, 0), on the side y = 0
  ASSERT_EQ(p[v], Vec3(3, 0, 0));
  p[v] = Vec3(3.25, -0.4, 0.7);
  slider.slide(topo, p, sliding, 0.0);
  EXPECT_NEAR((p[v] - Vec3(3.25, 0, 0)).norm(), 0, 1e-12);
  for (int w = 0; w < grid.vertexCount(); ++w)
    if (w != v) { EXPECT_TRUE(test::bitEqual(p[w], grid.positions[w])) << w; }
}
