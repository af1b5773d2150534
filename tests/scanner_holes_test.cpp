// SPDX-License-Identifier: GPL-3.0-or-later
// Holes as scanners leave them (issue 15): jagged borders, fragments floating inside a hole, thin
// parts cut through, holes one edge apart; and a mesh without holes, which the fill must leave as
// it is. Cut from CGAL's bunny scan (bunny00.off from Debian's libcgal-demo, fetched by
// scripts/setup.sh) where a real surface serves, from generated surfaces where the test needs an
// exact layout; every fill is checked for what a user expects of it, and scored against the
// surface that was cut away where there is one.
#include "self_intersections.h"
#include "surface_distance.h"
#include "test_meshes.h"

#include <elastica/hole_filling.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/mesh_quality.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

namespace elastica {
namespace {

const TriMesh& bunny() {
  static const TriMesh mesh = io::readMesh(std::string(ELASTICA_SAMPLE_MESH_DIR) + "/bunny00.off").mesh;
  return mesh;
}

double meanEdgeLength(const TriMesh& m) {
  double sum = 0;
  for (const Face& t : m.faces)
    for (int k = 0; k < 3; ++k) sum += (m.positions[t[k]] - m.positions[t[(k + 1) % 3]]).norm();
  return sum / (3.0 * m.faceCount());
}

// A tangent frame of `m` at its vertex nearest `near`: the normal averaged over the faces within
// `radius`.
struct Frame {
  Vec3 origin, normal, u, w;
  // Coordinates of p in the frame: (along u, along w, height).
  Vec3 local(const Vec3& p) const { return {(p - origin).dot(u), (p - origin).dot(w), (p - origin).dot(normal)}; }
};

Frame frameAt(const TriMesh& m, const Vec3& near, double radius) {
  Frame f;
  f.origin = m.positions[0];
  for (const Vec3& p : m.positions)
    if ((p - near).squaredNorm() < (f.origin - near).squaredNorm()) f.origin = p;
  f.normal = Vec3::Zero();
  for (const Face& t : m.faces) {
    const Vec3 c = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3;
    if ((c - f.origin).norm() < radius) f.normal += (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
  }
  f.normal.normalize();
  f.u = f.normal.unitOrthogonal();
  f.w = f.normal.cross(f.u);
  return f;
}

// `m` with the faces whose centroid `cut` selects removed, and those faces alone (the truth).
struct Cut {
  TriMesh holed, truth;
};

Cut cutWhere(const TriMesh& m, const std::function<bool(const Vec3&)>& cut) {
  std::vector<std::uint8_t> removed(m.faces.size(), 0);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const Face& t = m.faces[f];
    removed[f] = cut((m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3);
  }
  return {test::cutAway(m, cut), bench::facesOf(m, removed)};
}

// The faces of `m` with a corner within `radius` of `center`.
TriMesh near(const TriMesh& m, const Vec3& center, double radius) {
  std::vector<std::uint8_t> keep(m.faces.size(), 0);
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int v : m.faces[f]) keep[f] = keep[f] || (m.positions[v] - center).norm() < radius;
  return bench::facesOf(m, keep);
}

// What every fill owes its user: the input's vertices and faces bit for bit, a manifold,
// consistently oriented surface whose holes are all closed (`openEdges` border edges left: those
// of holes meant to stay open) with the Euler characteristic the closed shape has, and patches
// that cross nothing (checked within `radius` of `center`, where the patches are).
void expectSoundFill(const TriMesh& before, const TriMesh& after, const HoleFillReport& r, int openEdges, int euler,
                     const Vec3& center, double radius) {
  ASSERT_EQ(r.firstNewFace, before.faceCount());
  ASSERT_GE(after.vertexCount(), before.vertexCount());
  for (int i = 0; i < before.vertexCount(); ++i) ASSERT_EQ(after.positions[i], before.positions[i]) << i;
  for (int f = 0; f < before.faceCount(); ++f) ASSERT_EQ(after.faces[f], before.faces[f]) << f;
  const Topology topo(after.vertexCount(), after.faces);
  EXPECT_EQ(topo.boundaryEdgeCount(), openEdges);
  EXPECT_EQ(topo.nonManifoldVertexCount(), 0);
  EXPECT_EQ(topo.inconsistentEdgeCount(), 0);
  EXPECT_EQ(topo.eulerCharacteristic(), euler);
  EXPECT_EQ(test::selfIntersections(near(after, center, radius)), 0);
}

// ------------------------------------------------------------------ jagged borders

// A sawtooth border: the hole's radius in the tangent plane swings ±40 % around R0 in 8 teeth
// (each about 6 edges deep and 6 wide), as where a scanner's view grazed a surface. (Sharper or
// more teeth cut this way leave faces hanging at a vertex in the hole: borders that pass twice
// through a vertex, which the fill leaves open; see the report.) The border has
// corners far sharper than anything inside the patch; the fill must still close it with a patch
// that follows the bunny's flank: closer to the cut-away surface than the flat minimum-weight
// triangulation the pipeline starts from, and within a small fraction of the hole's size.
TEST(ScannerHoles, SawtoothBorderIsFilledAlongTheSurface) {
  const TriMesh& full = bunny();
  const double h = meanEdgeLength(full), r0 = 8 * h;
  const Frame frame = frameAt(full, Vec3(0.383, -0.074, 0.132), r0);  // the bunny's right flank
  const double pi = std::acos(-1.0);
  const Cut cut = cutWhere(full, [&](const Vec3& c) {
    const Vec3 q = frame.local(c);
    const double turns = 8 * std::atan2(q.y(), q.x()) / (2 * pi);
    const double tooth = 2 * std::abs(2 * (turns - std::floor(turns + 0.5))) - 1;  // a triangle wave in [−1, 1]
    return std::hypot(q.x(), q.y()) < r0 * (1 + 0.4 * tooth) && std::abs(q.z()) < r0;
  });
  TriMesh flat = cut.holed, filled = cut.holed;
  HoleFillOptions triangulationOnly;
  triangulationOnly.stopAfter = FillStage::Triangulation;
  fillHoles(flat, triangulationOnly);
  const HoleFillReport r = fillHoles(filled, {});
  ASSERT_EQ(r.holes.size(), 1u);
  const HoleReport& hole = r.holes[0];
  ASSERT_TRUE(hole.filled) << hole.reason;
  EXPECT_TRUE(hole.reason.empty()) << hole.reason;
  EXPECT_GE(hole.borderEdges, 60);  // jagged: a round hole of radius R0 has about 2π·8 = 50
  expectSoundFill(cut.holed, filled, r, 0, 2, frame.origin, 3 * r0);

  // The teeth are sharp corners of the border; inside, the patch has no slivers.
  EXPECT_LT(hole.borderBoundDegrees, 60);
  EXPECT_GE(hole.minAngleDegrees, std::min(20.0, hole.borderBoundDegrees)) << "border bound " << hole.borderBoundDegrees;

  std::vector<std::uint8_t> isNew = test::newFaceFlags(filled, r), isFlat(flat.faces.size(), 0);
  for (int f = cut.holed.faceCount(); f < flat.faceCount(); ++f) isFlat[f] = 1;
  const TriMesh patch = bench::facesOf(filled, isNew), flatPatch = bench::facesOf(flat, isFlat);
  const double there = bench::sampledDistance(patch, cut.truth, 4).rms, back = bench::sampledDistance(cut.truth, patch, 4).rms;
  const double flatThere = bench::sampledDistance(flatPatch, cut.truth, 4).rms, flatBack = bench::sampledDistance(cut.truth, flatPatch, 4).rms;
  std::printf("sawtooth hole: %d border edges, %d new vertices, smallest angle %.1f° (border %.1f°), RMS %.4f / %.4f of R0 "
              "(flat fill %.4f / %.4f)\n",
              hole.borderEdges, hole.newVertices, hole.minAngleDegrees, hole.borderBoundDegrees, there / r0, back / r0, flatThere / r0,
              flatBack / r0);
  // Measured: 0.0027 / 0.0031 of R0, the flat fill 0.0048 / 0.0173.
  EXPECT_LT(there, flatThere);
  EXPECT_LT(back, flatBack);
  EXPECT_LT(there, 0.01 * r0);
  EXPECT_LT(back, 0.01 * r0);
}

// ------------------------------------------------------------------ islands

// An annulus cut from the flank leaves a disc of faces floating inside the hole: a separate piece
// whose own border is a second loop. A disc patch over the outer loop would run through the
// island, and one over the island's loop would close the island onto itself; the fill leaves both
// open, says why in both reports, and changes nothing. Moved out of the hole (the same piece, far
// away), the island is a sheet of its own, and both loops are filled as before.
TEST(ScannerHoles, IslandInsideAHoleIsReportedAndBothLoopsLeftOpen) {
  const TriMesh& full = bunny();
  const double h = meanEdgeLength(full), inner = 3 * h, outer = 7 * h;
  const Frame frame = frameAt(full, Vec3(0.383, -0.074, 0.132), outer);
  const Cut cut = cutWhere(full, [&](const Vec3& c) {
    const Vec3 q = frame.local(c);
    const double r = std::hypot(q.x(), q.y());
    return r > inner && r < outer && std::abs(q.z()) < outer;
  });
  TriMesh mesh = cut.holed;
  const HoleFillReport r = fillHoles(mesh, {});
  ASSERT_EQ(r.holes.size(), 2u);
  for (const HoleReport& hole : r.holes) {
    EXPECT_FALSE(hole.filled);
    EXPECT_NE(hole.reason.find("island"), std::string::npos) << hole.reason;
  }
  const HoleReport& big = r.holes[0].borderEdges > r.holes[1].borderEdges ? r.holes[0] : r.holes[1];
  EXPECT_NE(big.reason.find("a patch would cross"), std::string::npos) << big.reason;
  EXPECT_EQ(mesh.positions, cut.holed.positions);
  EXPECT_EQ(mesh.faces, cut.holed.faces);

  // The same piece moved out of the hole (by twice the model's size along the normal).
  TriMesh apart = cut.holed;
  std::vector<std::uint8_t> onIsland(apart.positions.size(), 0);
  for (int v = 0; v < apart.vertexCount(); ++v) {
    const Vec3 q = frame.local(apart.positions[v]);
    onIsland[v] = std::hypot(q.x(), q.y()) < (inner + outer) / 2 && std::abs(q.z()) < outer;
  }
  for (int v = 0; v < apart.vertexCount(); ++v)
    if (onIsland[v]) apart.positions[v] += 2 * frame.normal;
  // Only the island's vertices lie within the cut's radius: the moved vertices are exactly its own.
  for (const Face& t : apart.faces) ASSERT_TRUE(onIsland[t[0]] == onIsland[t[1]] && onIsland[t[1]] == onIsland[t[2]]);
  // The hole is filled; the fragment, now a piece of its own, is an open disc whose border is its
  // outer rim (rim_rule.h): left open, unless rims are to be closed too.
  TriMesh apartToo = apart;
  const HoleFillReport moved = fillHoles(apart, {});
  ASSERT_EQ(moved.holes.size(), 2u);
  for (const HoleReport& hole : moved.holes)
    EXPECT_EQ(hole.filled, !hole.rim) << hole.borderEdges << ": " << hole.reason;
  EXPECT_EQ(moved.filledCount(), 1);
  HoleFillOptions closeRims;
  closeRims.closeRims = true;
  const HoleFillReport both = fillHoles(apartToo, closeRims);
  for (const HoleReport& hole : both.holes) EXPECT_TRUE(hole.filled) << hole.borderEdges << ": " << hole.reason;
}

// ------------------------------------------------------------------ thin features

// A tube a few edges round (a torus whose tube has 12 edges around, 4 across) cut through: two loops, one at
// each end of the gap. Both are filled, each with a cap that stays on its own side of the gap and
// close to the tube (a G¹ cap rounds off within about one tube radius of the core circle): a
// closed surface of genus 0.
TEST(ScannerHoles, TubeCutThroughIsClosedAtBothEnds) {
  const double bigR = 3, r = 0.5, pi = std::acos(-1.0);
  const TriMesh torus = shapes::torus(bigR, r, 64, 12);
  const double gap = 12 * pi / 180;  // 2 × 12°: four of the 64 segments
  const TriMesh holed = test::cutAway(torus, [&](const Vec3& c) { return std::abs(std::atan2(c.y(), c.x())) < gap; });
  TriMesh mesh = holed;
  const HoleFillReport rep = fillHoles(mesh, {});
  ASSERT_EQ(rep.holes.size(), 2u);
  int first = holed.vertexCount();
  for (const HoleReport& hole : rep.holes) {
    EXPECT_TRUE(hole.filled) << hole.reason;
    EXPECT_TRUE(hole.reason.empty()) << hole.reason;
    EXPECT_EQ(hole.borderEdges, 12);
    EXPECT_GE(hole.minAngleDegrees, 20);
    EXPECT_GT(hole.newVertices, 0);
    std::printf("tube end: %d border edges, %d new vertices, smallest angle %.1f°\n", hole.borderEdges, hole.newVertices,
                hole.minAngleDegrees);
    // The cap's own side of the gap.
    double side = 0;
    for (int i = first; i < first + hole.newVertices; ++i) side += std::atan2(mesh.positions[i].y(), mesh.positions[i].x());
    for (int i = first; i < first + hole.newVertices; ++i) {
      const Vec3& p = mesh.positions[i];
      const double phi = std::atan2(p.y(), p.x());
      EXPECT_GT(phi * side, 0) << "a cap crosses the middle of the gap";
      EXPECT_LT(std::abs(phi), gap);
      const Vec3 core = bigR * Vec3(std::cos(phi), std::sin(phi), 0);
      EXPECT_LT((p - core).norm(), 1.25 * r);
    }
    first += hole.newVertices;
  }
  expectSoundFill(holed, mesh, rep, 0, 2, Vec3(bigR, 0, 0), 2 * bigR);
}

// ------------------------------------------------------------------ holes one edge apart

// Two rectangular holes in a grid draped over a sphere, separated by one column of quads: the
// borders are one edge apart, joined by the column's edges. Both are filled, the column stays (its
// faces bit for bit), each patch stays on its own side of it, and the patches follow the sphere.
TEST(ScannerHoles, TwoHolesOneEdgeApartAreBothFilledOnTheirOwnSides) {
  const int n = 24;
  const double rho = 12;  // sphere radius in grid spacings
  TriMesh grid = shapes::grid(n, n, 1.0);
  const std::vector<Vec3> flat = grid.positions;
  for (Vec3& p : grid.positions) p = rho * Vec3(p.x() - n / 2.0, p.y() - n / 2.0, rho).normalized();
  // Quads by their column i and row j in the flat grid: hole A takes columns 6–11, hole B 13–18
  // (rows 6–17); column 12 stays.
  auto quad = [&](const Face& t) {
    const Vec3 c = (flat[t[0]] + flat[t[1]] + flat[t[2]]) / 3;
    return std::make_pair(static_cast<int>(std::floor(c.x())), static_cast<int>(std::floor(c.y())));
  };
  auto inA = [](int i, int j) { return i >= 6 && i <= 11 && j >= 6 && j <= 17; };
  auto inB = [](int i, int j) { return i >= 13 && i <= 18 && j >= 6 && j <= 17; };
  TriMesh holed;
  holed.positions = grid.positions;
  for (const Face& t : grid.faces) {
    const auto [i, j] = quad(t);
    if (!inA(i, j) && !inB(i, j)) holed.faces.push_back(t);
  }
  // Interior vertices of the holes keep no face: drop them (every vertex of a read mesh has one).
  holed = test::cutAway(holed, [](const Vec3&) { return false; });
  TriMesh mesh = holed;
  HoleFillOptions opt;
  opt.maxHoleEdges = 60;  // the holes (36 edges each); the grid's rim (96) stays open
  const HoleFillReport r = fillHoles(mesh, opt);
  ASSERT_EQ(r.filledCount(), 2);
  // Flat-grid coordinate of a point on the sphere (the inverse of the draping).
  auto column = [&](const Vec3& p) { return rho * p.x() / p.z() + n / 2.0; };
  int first = holed.vertexCount();
  for (const HoleReport& hole : r.holes) {
    if (!hole.filled) continue;
    EXPECT_TRUE(hole.reason.empty()) << hole.reason;
    EXPECT_EQ(hole.borderEdges, 36);
    EXPECT_GE(hole.minAngleDegrees, 20);
    ASSERT_GT(hole.newVertices, 0);
    std::printf("hole one edge from another: %d border edges, %d new vertices, smallest angle %.1f°\n", hole.borderEdges,
                hole.newVertices, hole.minAngleDegrees);
    const bool isA = column(mesh.positions[first]) < 12.5;
    for (int i = first; i < first + hole.newVertices; ++i) {
      const Vec3& p = mesh.positions[i];
      if (isA) EXPECT_LT(column(p), 12.0) << "patch A reaches into the column";
      else EXPECT_GT(column(p), 13.0) << "patch B reaches into the column";
      EXPECT_LT(std::abs(p.norm() - rho), 0.01 * rho);  // on the sphere to 1 % of its radius
    }
    first += hole.newVertices;
  }
  expectSoundFill(holed, mesh, r, 4 * n, 1, Vec3(0, 0, rho), 2 * rho);
}

// ------------------------------------------------------------------ the input after a failure

// The fill works on the input itself (no copy): welds rewire its faces at once and patches are
// appended at the end. Whatever throws midway, the input comes back as it was: here a progress
// callback that throws during a later hole's flow, on CGAL's elephant with holes, whose borders
// pass through copies of points that the fill welds before its first patch.
TEST(ScannerHoles, InputIsRestoredWhenTheFillThrowsMidway) {
  const TriMesh before = io::readMesh(std::string(ELASTICA_SAMPLE_MESH_DIR) + "/elephant-with-holes.off").mesh;
  {
    TriMesh mesh = before;
    const HoleFillReport r = fillHoles(mesh, {});
    ASSERT_FALSE(r.welds.empty());  // the welds this test must see undone
    ASSERT_GT(r.filledCount(), 10);
  }
  TriMesh mesh = before;
  HoleFillOptions opt;
  int calls = 0;
  opt.flow.progress = [&](const FlowProgress&) {
    if (++calls == 40) throw std::runtime_error("stop here");
    return true;
  };
  EXPECT_THROW(fillHoles(mesh, opt), std::runtime_error);
  EXPECT_EQ(calls, 40);
  EXPECT_EQ(mesh.positions, before.positions);
  EXPECT_EQ(mesh.faces, before.faces);
}

// ------------------------------------------------------------------ no holes

// A closed mesh has nothing to fill: the fill returns it as it was, element for element, whatever
// the stage asked for, and says there were no holes.
TEST(ScannerHoles, MeshWithoutHolesIsLeftAsItIs) {
  const std::vector<std::pair<std::string, TriMesh>> meshes = {
      {"bunny00", bunny()},
      {"elephant", io::readMesh(std::string(ELASTICA_SAMPLE_MESH_DIR) + "/elephant.off").mesh},
      {"icosphere", shapes::icosphere(1, 3)},
      {"torus", shapes::torus(3, 1, 24, 12)}};
  for (const auto& [name, closed] : meshes) {
    for (FillStage stage : {FillStage::Triangulation, FillStage::Flow}) {
      TriMesh mesh = closed;
      HoleFillOptions opt;
      opt.stopAfter = stage;
      const HoleFillReport r = fillHoles(mesh, opt);
      EXPECT_TRUE(r.holes.empty()) << name;
      EXPECT_TRUE(r.welds.empty()) << name;
      EXPECT_EQ(r.firstNewFace, closed.faceCount()) << name;
      EXPECT_EQ(mesh.positions, closed.positions) << name;
      EXPECT_EQ(mesh.faces, closed.faces) << name;
    }
  }
}

}  // namespace
}  // namespace elastica
