// SPDX-License-Identifier: GPL-3.0-or-later
// The rim rule (restoration/rim_rule.h): an open surface's outer border stays open, the holes
// inside it are filled. Each case prints its row of docs/restoration.md's table.
#include "file_helpers.h"
#include "test_meshes.h"

#include <elastica/hole_filling.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>
#include "restoration/hole_boundary.h"
#include "restoration/rim_rule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace elastica {
namespace {

using test::cutAway;

// A flat 20×20 sheet centred on the origin, cut to what `keep` keeps (by face centroid).
TriMesh sheet(const std::function<bool(double x, double y)>& keep) {
  TriMesh g = shapes::grid(20, 20, 1.0);
  for (Vec3& p : g.positions) p -= Vec3(10, 10, 0);
  return cutAway(g, [&](const Vec3& c) { return !keep(c.x(), c.y()); });
}
bool within(double x, double y, double cx, double cy, double r) { return std::hypot(x - cx, y - cy) < r; }

struct Case {
  const char* name;
  TriMesh mesh;
  int loops, rims;
};

std::vector<Case> cases() {
  const std::string data = ELASTICA_DATA_DIR;
  TriMesh triangle;
  triangle.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  triangle.faces = {{0, 1, 2}};
  auto capCut = [](double degrees) {
    const double c = std::cos(degrees * M_PI / 180);
    return cutAway(shapes::icosphere(1, 4), [&](const Vec3& p) { return p.z() / p.norm() > c; });
  };
  return {
      {"disc (radius 9.5)", sheet([](double x, double y) { return within(x, y, 0, 0, 9.5); }), 1, 1},
      {"annulus (radii 9.5 and 4)",
       sheet([](double x, double y) { return within(x, y, 0, 0, 9.5) && !within(x, y, 0, 0, 4); }), 2, 1},
      {"disc with three holes", sheet([](double x, double y) {
         return within(x, y, 0, 0, 9.5) && !within(x, y, 4, 0, 2) && !within(x, y, -3, 3, 2) && !within(x, y, -3, -4, 1.5);
       }), 4, 1},
      {"20x20 grid, hole in the middle", sheet([](double x, double y) { return !within(x, y, 0, 0, 3); }), 2, 1},
      {"lone triangle", triangle, 1, 1},
      {"bunny_flank_hole.ply", io::readMesh(data + "/bunny_flank_hole.ply").mesh, 1, 0},
      {"disc, z-noise 0.3 of an edge", test::jittered(sheet([](double x, double y) { return within(x, y, 0, 0, 9.5); }), 0.3),
       1, 1},
      {"open tube, length 4 radii", shapes::cylinder(1, 4, 32, 16), 2, 0},
      {"sphere, 70 deg cap cut", capCut(70), 1, 0},
      {"sphere, 110 deg cap cut (a bowl)", capCut(110), 1, 1},
  };
}

std::vector<RimMeasure> measure(const TriMesh& mesh, std::vector<HoleLoop>& loops) {
  const Topology topo(mesh.vertexCount(), mesh.faces);
  loops = findHoleLoops(topo);
  const VertexFaces adjacency(mesh.vertexCount(), mesh.faces);
  return classifyRims(mesh, loops, [&](int v) { return cornerAngleSum(mesh, adjacency.faces(v), v); });
}

// The rule on each shape, at three scales (it is scale-free), with the measures it read.
TEST(RimRule, SeparatesRimsFromHoles) {
  std::printf("| shape | loops | loop: edges, turning, spanned area / piece's area | rims |\n|---|---:|---|---:|\n");
  for (const Case& c : cases()) {
    std::vector<HoleLoop> loops;
    const std::vector<RimMeasure> m = measure(c.mesh, loops);
    ASSERT_EQ(static_cast<int>(loops.size()), c.loops) << c.name;
    int rims = 0;
    std::string row;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      rims += m[l].rim;
      char cell[120];
      std::snprintf(cell, sizeof cell, "%s%d, %+.0f°, %s%s", row.empty() ? "" : "; ", loops[l].edgeCount(),
                    m[l].turning * 180 / M_PI, m[l].turning > 0 ? (std::to_string(std::lround(100 * m[l].areaRatio)) + " %").c_str() : "–",
                    m[l].rim ? " **rim**" : "");
      row += cell;
    }
    std::printf("| %s | %d | %s | %d |\n", c.name, c.loops, row.c_str(), rims);
    EXPECT_EQ(rims, c.rims) << c.name;
    for (double s : {1e-4, 1e4}) {
      std::vector<HoleLoop> scaledLoops;
      const std::vector<RimMeasure> ms = measure(test::scaled(c.mesh, s), scaledLoops);
      for (std::size_t l = 0; l < loops.size(); ++l) EXPECT_EQ(ms[l].rim, m[l].rim) << c.name << " at scale " << s;
    }
  }
}

// fillHoles: rims stay open by default (the mesh bit for bit when there is nothing else), the
// holes inside are filled; closeRims closes the rims too.
TEST(RimRule, FillLeavesRimsOpenUnlessAsked) {
  for (const Case& c : cases()) {
    if (std::string(c.name).rfind("sphere", 0) == 0 || std::string(c.name).rfind("open tube", 0) == 0) continue;
    TriMesh mesh = c.mesh;
    const HoleFillReport r = fillHoles(mesh, {});
    ASSERT_EQ(static_cast<int>(r.holes.size()), c.loops) << c.name;
    int rims = 0;
    for (const HoleReport& h : r.holes) {
      rims += h.rim;
      EXPECT_EQ(h.filled, !h.rim) << c.name << ": " << h.reason;
      if (h.rim) {
        EXPECT_NE(h.reason.find("outer rim"), std::string::npos) << h.reason;
      }
    }
    EXPECT_EQ(rims, c.rims) << c.name;
    EXPECT_EQ(Topology(mesh.vertexCount(), mesh.faces).boundaryEdgeCount() > 0, c.rims > 0) << c.name;  // only the rims stay open
    if (c.loops == c.rims) {  // nothing to fill: unchanged
      EXPECT_EQ(mesh.positions, c.mesh.positions) << c.name;
      EXPECT_EQ(mesh.faces, c.mesh.faces) << c.name;
    }
  }
  // A lone triangle is not "filled" with a back-to-back face, unless asked; a disc closes into a
  // pillow only when asked.
  for (const char* name : {"lone triangle", "disc (radius 9.5)"}) {
    for (const Case& c : cases()) {
      if (c.name != std::string(name)) continue;
      TriMesh mesh = c.mesh;
      HoleFillOptions opt;
      opt.closeRims = true;
      const HoleFillReport r = fillHoles(mesh, opt);
      ASSERT_EQ(r.holes.size(), 1u);
      EXPECT_TRUE(r.holes[0].rim && r.holes[0].filled) << name << ": " << r.holes[0].reason;
      EXPECT_EQ(Topology(mesh.vertexCount(), mesh.faces).boundaryEdgeCount(), 0) << name;
    }
  }
}

}  // namespace
}  // namespace elastica
