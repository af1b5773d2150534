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

// Long thin faces among small ones (a CAD rod's sides) go through the every-face path.
TEST(SelfIntersection, VeryLargeFacesAreTestedToo) {
  TriMesh m = shapes::icosphere(0.01, 3);
  const int n = m.vertexCount();
  m.positions.insert(m.positions.end(), {Vec3(-100, 0, 0.001), Vec3(100, 0, 0.001), Vec3(0, 0.002, 100)});
  m.faces.push_back({n, n + 1, n + 2});  // a huge face through the tiny sphere
  EXPECT_TRUE(selfIntersects(m));
  EXPECT_EQ(selfIntersectingFaces(m), vcglibSelfIntersections(m));
}
