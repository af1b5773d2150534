// SPDX-License-Identifier: GPL-3.0-or-later
// The flow's embedding guard (mesh/self_intersection.h) against constructed cases and against
// vcglib's SelfIntersections, an independent implementation of the same definition.
#include <elastica/shapes.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>
#include "mesh/self_intersection.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace elastica;

namespace {

// Two triangles; the second is shifted by `dz` along z through the first's plane.
TriMesh twoTriangles(double dz) {
  TriMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0),                  // in the plane z = 0
                 Vec3(0.5, 0.5, -1 + dz), Vec3(0.5, 0.5, 1 + dz), Vec3(3, 3, dz)};  // a vertical fin
  m.faces = {{0, 1, 2}, {3, 4, 5}};
  return m;
}

// The faces vcglib's Clean::SelfIntersections reports, each once, ascending (its list repeats a
// face once per face it crosses).
std::vector<int> vcglibSelfIntersections(const TriMesh& m) {
  VcgMesh vm;
  fromTriMesh(m, vm);
  vcg::tri::UpdateBounding<VcgMesh>::Box(vm);
  std::vector<VcgFace*> hits;
  vcg::tri::Clean<VcgMesh>::SelfIntersections(vm, hits);
  std::vector<int> faces;
  for (VcgFace* f : hits) faces.push_back(static_cast<int>(f - &vm.face[0]));
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

}  // namespace

TEST(SelfIntersection, CrossingAndSeparateTriangles) {
  EXPECT_EQ(selfIntersectingFaces(twoTriangles(0)), (std::vector<int>{0, 1}));  // the fin pierces the triangle
  EXPECT_TRUE(selfIntersects(twoTriangles(0)));
  EXPECT_TRUE(selfIntersectingFaces(twoTriangles(5)).empty());  // lifted clear of it
  EXPECT_FALSE(selfIntersects(twoTriangles(5)));
}

TEST(SelfIntersection, ClosedSurfacesAreEmbedded) {
  EXPECT_FALSE(selfIntersects(shapes::icosphere(1.0, 3)));
  EXPECT_FALSE(selfIntersects(shapes::torus(3, 1, 48, 16)));
  EXPECT_FALSE(selfIntersects(shapes::torus(1.2, 1, 24, 12)));  // a fat torus: its inner faces come close
}

// A vertex of a sphere pushed through to the far side: the faces it drags along cross the far
// side. The faces found are vcglib's, pair definition and all.
TEST(SelfIntersection, AgreesWithVcglibOnAPushedThroughSphere) {
  TriMesh m = shapes::icosphere(1.0, 3);
  m.positions[0] = -1.4 * m.positions[0];
  const std::vector<int> ours = selfIntersectingFaces(m);
  EXPECT_GT(ours.size(), 0u);
  EXPECT_EQ(ours, vcglibSelfIntersections(m));
}

// The local form skips pairs in which neither face is flagged: flagging only faces far from the
// crossing finds nothing, flagging one of the crossing faces finds it.
TEST(SelfIntersection, LocalTestLooksOnlyAtFlaggedFaces) {
  const TriMesh m = twoTriangles(0);
  std::vector<std::uint8_t> none{0, 0}, second{0, 1};
  EXPECT_FALSE(selfIntersects(m, &none));
  EXPECT_TRUE(selfIntersects(m, &second));
}

// After edge flips (the same positions, some faces rewritten) only pairs with a rewritten face are
// tested: a rewritten face that crosses is found, a crossing the flags say was tested before is not
// looked at again, and where the positions moved every flagged pair is tested.
TEST(SelfIntersection, RewrittenFacesAreTestedAlone) {
  const std::vector<std::uint8_t> active{1, 1, 1};
  // The fin pierces the triangle (as if the guard had passed it), and a third face beside the fin
  // is rewritten with its corners turned: only its own pairs are tested, and it crosses nothing.
  TriMesh crossing = twoTriangles(0);
  crossing.positions.push_back(Vec3(9, 8, 9));
  crossing.positions.push_back(Vec3(9, 0, 9));
  crossing.faces.push_back({4, 6, 7});
  TriMesh flipped = crossing;
  flipped.faces[2] = {4, 7, 6};
  EXPECT_TRUE(selfIntersects(flipped, &active));
  EXPECT_FALSE(rewrittenFacesCross(crossing, flipped, active)) << "only the rewritten face's pairs";
  TriMesh moved = flipped;
  moved.positions[7] += Vec3(0, 0, 1e-3);
  EXPECT_TRUE(rewrittenFacesCross(crossing, moved, active)) << "the positions moved: every flagged pair";
  // A rewritten face that runs from below the triangle up to the fin, through the triangle.
  TriMesh clear = twoTriangles(5);
  clear.positions.push_back(Vec3(0.5, 0.5, -1));
  clear.faces.push_back({3, 4, 5});
  TriMesh through = clear;
  through.faces[2] = {6, 4, 5};
  EXPECT_FALSE(selfIntersects(clear));
  EXPECT_TRUE(rewrittenFacesCross(clear, through, active));
}

// A grid of many cells per face (two small clusters far apart) is keyed and sorted, one of few
// cells is bucketed: both find vcglib's faces.
TEST(SelfIntersection, SparseAndDenseGridsAgreeWithVcglib) {
  for (const double apart : {0.0, 1e4}) {
    TriMesh m = shapes::icosphere(1.0, 2);
    m.positions[0] = -1.4 * m.positions[0];
    const TriMesh far = shapes::icosphere(1.0, 2);
    const int offset = m.vertexCount();
    for (const Vec3& p : far.positions) m.positions.push_back(p + Vec3(apart + 3, 0, 0));
    for (const Face& f : far.faces) m.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
    const std::vector<int> ours = selfIntersectingFaces(m);
    EXPECT_GT(ours.size(), 0u);
    EXPECT_EQ(ours, vcglibSelfIntersections(m)) << "clusters " << apart << " apart";
  }
}

// Long thin faces among small ones (a CAD rod's sides) go through the every-face path.
TEST(SelfIntersection, VeryLargeFacesAreTestedToo) {
  TriMesh m = shapes::icosphere(0.01, 3);
  const int n = m.vertexCount();
  m.positions.insert(m.positions.end(), {Vec3(-100, 0, 0.001), Vec3(100, 0, 0.001), Vec3(0, 0.002, 100)});
  m.faces.push_back({n, n + 1, n + 2});  // a huge face through the tiny sphere
  EXPECT_TRUE(selfIntersects(m));
  EXPECT_EQ(selfIntersectingFaces(m), vcglibSelfIntersections(m));
}
