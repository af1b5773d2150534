// SPDX-License-Identifier: GPL-3.0-or-later
// Isotropic remeshing of a hole's patch (mesh/patch_remeshing, Botsch & Kobbelt 2004):
// only the patch's own vertices and faces change; slivers go.
#include "exact_compare.h"
#include "hole_patches.h"
#include "test_meshes.h"

#include <elastica/mesh_quality.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>
#include "restoration/biharmonic_embedding.h"
#include "restoration/patch_refinement.h"
#include "mesh/patch_remeshing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

using namespace elastica;

namespace {

// Remeshes `h`'s patch toward `sigma` and checks what remeshPatch promises whatever the shape: the
// vertices before firstNew bit for bit, every face outside the patch at its index with its value,
// sigma and the flags following the mesh, and a consistently oriented manifold with the same
// boundary and Euler characteristic. Returns the patch's smallest angle before and after, in degrees.
std::pair<double, double> remeshAndCheck(test::PatchedHole& h, std::vector<double>& sigma) {
  const TriMesh before = h.mesh;
  const std::vector<std::uint8_t> patchBefore = h.patchFace;
  const double angleBefore = smallestAngleDegrees(h.mesh, h.patchFace);
  remeshPatch(h.mesh, h.patchFace, sigma, h.firstNew);
  const TriMesh& after = h.mesh;
  EXPECT_GE(after.vertexCount(), h.firstNew);
  for (int v = 0; v < h.firstNew && v < after.vertexCount(); ++v)
    EXPECT_TRUE(test::bitEqual(after.positions[v], before.positions[v])) << "vertex " << v;
  EXPECT_EQ(h.patchFace.size(), after.faces.size());
  EXPECT_EQ(sigma.size(), after.positions.size());
  for (int f = 0; f < before.faceCount() && f < after.faceCount(); ++f) {
    if (patchBefore[f]) continue;
    EXPECT_FALSE(h.patchFace[f]) << "face " << f;
    EXPECT_EQ(after.faces[f], before.faces[f]) << "face " << f;
  }
  const Topology t0(before.vertexCount(), before.faces), t1(after.vertexCount(), after.faces);
  EXPECT_EQ(t1.inconsistentEdgeCount(), 0);
  EXPECT_EQ(t1.nonManifoldVertexCount(), 0);
  EXPECT_EQ(t1.boundaryEdgeCount(), t0.boundaryEdgeCount());
  EXPECT_EQ(t1.eulerCharacteristic(), t0.eulerCharacteristic());
  return {angleBefore, smallestAngleDegrees(h.mesh, h.patchFace)};
}

}  // namespace

// A flat patch (the 6×6 hole of a 12×12 unit grid, triangulated and refined) whose new vertices are
// thrown about in the plane by up to 0.3 has slivers. Remeshing toward σ = 1 keeps it exactly in
// the plane (|z| ≤ 1e-12: splits at midpoints, moves within the tangent plane), tiling the same 36
// units of area (to 1e-9) without a fold, and raises the smallest angle above 20° (what the
// restoration calls a sliver, hole_filling.cpp's kRemeshStartBelowDegrees).
TEST(PatchRemeshing, RaisesTheSmallestAngleOfAFlatPatch) {
  test::PatchedHole h = test::triangulateSmallestHole(test::cutAway(shapes::grid(12, 12, 1.0), [](const Vec3& c) {
                          return c.x() > 3 && c.x() < 9 && c.y() > 3 && c.y() < 9;
                        })).value();
  std::vector<double> sigma(h.mesh.positions.size(), 1.0);
  refinePatch(h.mesh, h.patchFace, sigma);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int v = h.firstNew; v < h.mesh.vertexCount(); ++v) h.mesh.positions[v] += Vec3(u(rng), u(rng), 0);
  for (int f = 0; f < h.mesh.faceCount(); ++f) {  // slivers, but no fold yet
    const Face& t = h.mesh.faces[f];
    ASSERT_GT((h.mesh.positions[t[1]] - h.mesh.positions[t[0]]).cross(h.mesh.positions[t[2]] - h.mesh.positions[t[0]]).z(), 0);
  }
  const auto [angleBefore, angleAfter] = remeshAndCheck(h, sigma);
  EXPECT_LT(angleBefore, 20);
  EXPECT_GT(angleAfter, 20);
  double area = 0;
  for (int f = 0; f < h.mesh.faceCount(); ++f) {
    if (!h.patchFace[f]) continue;
    const Face& t = h.mesh.faces[f];
    const Vec3 n = (h.mesh.positions[t[1]] - h.mesh.positions[t[0]]).cross(h.mesh.positions[t[2]] - h.mesh.positions[t[0]]);
    EXPECT_GT(n.z(), 0) << "face " << f;
    area += 0.5 * n.norm();
  }
  EXPECT_NEAR(area, 36.0, 1e-9);
  for (int v = h.firstNew; v < h.mesh.vertexCount(); ++v) EXPECT_NEAR(h.mesh.positions[v].z(), 0, 1e-12) << v;
}

// The restoration's own case: a deep hole (the cap within 110° of the pole cut from a 2,562-vertex
// unit icosphere) whose bi-Laplace start, built as the restoration builds it (refine, solve, refine
// where the solve stretched it, solve), has slivers (about 5°). Remeshing keeps the sphere's other
// vertices bit for bit, closes it up as a sphere (Euler characteristic 2) and raises the patch's
// smallest angle above 20°.
TEST(PatchRemeshing, RemovesTheSliversOfADeepBiharmonicPatch) {
  const double c = std::cos(110 * M_PI / 180);
  test::PatchedHole h = test::triangulateSmallestHole(test::cutAway(shapes::icosphere(1, 4), [&](const Vec3& p) {
                          return p.z() / p.norm() > c;
                        })).value();
  // σ: the mean length of the mesh edges at each vertex before the hole was closed (the restoration's).
  TriMesh cut = h.mesh;
  cut.faces.resize(h.firstPatchFace);
  const Topology topo(cut.vertexCount(), cut.faces);
  std::vector<double> sigma(h.mesh.positions.size(), 0);
  for (int v = 0; v < h.firstNew; ++v) {
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) sigma[v] += (h.mesh.positions[topo.ringVertex(k)] - h.mesh.positions[v]).norm();
    sigma[v] /= topo.valence(v);
  }
  refinePatch(h.mesh, h.patchFace, sigma);
  std::vector<std::uint8_t> free(h.mesh.positions.size(), 0);
  std::fill(free.begin() + h.firstNew, free.end(), 1);
  solveBiharmonic(h.mesh, free);
  const int refined = h.mesh.vertexCount();  // as the restoration does: refine where the solve stretched it, solve again
  refinePatch(h.mesh, h.patchFace, sigma);
  free.resize(h.mesh.positions.size(), 1);
  if (h.mesh.vertexCount() > refined) solveBiharmonic(h.mesh, free);
  const auto [angleBefore, angleAfter] = remeshAndCheck(h, sigma);
  EXPECT_LT(angleBefore, 20);
  EXPECT_GT(angleAfter, 20);
  EXPECT_EQ(Topology(h.mesh.vertexCount(), h.mesh.faces).eulerCharacteristic(), 2);
}

namespace {

// A 30×30 unit grid whose vertices two rows or more inside its border are movable, and the faces
// of three movable vertices the region (the flow's moving region on a mesh with a border: the
// faces of the fixed rows lie between the region's ones up to the end of the face list).
struct BorderedGrid {
  TriMesh mesh = shapes::grid(30, 30);
  std::vector<std::uint8_t> movable, region;
  BorderedGrid() {
    for (int v = 0; v < mesh.vertexCount(); ++v) {
      const int i = v % 31, j = v / 31;
      movable.push_back(i >= 2 && j >= 2 && i <= 28 && j <= 28);
    }
    for (const Face& t : mesh.faces) region.push_back(movable[t[0]] && movable[t[1]] && movable[t[2]]);
  }
  // Remeshes the region toward edges `sigma` long, with or without PatchRemeshingOptions::regionMayShrink.
  void remesh(double sigma, bool mayShrink) {
    std::vector<double> lengths(mesh.positions.size(), sigma);
    PatchRemeshingOptions opt;
    opt.regionMayShrink = mayShrink;
    remeshRegion(mesh, region, lengths, movable, opt);
  }
  // The positions of the vertices not movable, and the faces not in the region as their fixed
  // corners' positions (a movable corner as NaN: it may move or be joined to another), in their order.
  std::vector<Vec3> fixedPositions() const {
    std::vector<Vec3> out;
    for (int v = 0; v < mesh.vertexCount(); ++v)
      if (!movable[v]) out.push_back(mesh.positions[v]);
    return out;
  }
  std::vector<std::array<Vec3, 3>> outsideFaces() const {
    std::vector<std::array<Vec3, 3>> out;
    for (int f = 0; f < mesh.faceCount(); ++f) {
      const Face& t = mesh.faces[f];
      if (region[f]) continue;
      std::array<Vec3, 3> corners;
      for (int c = 0; c < 3; ++c) corners[c] = movable[t[c]] ? Vec3::Constant(std::nan("")) : mesh.positions[t[c]];
      out.push_back(corners);
    }
    return out;
  }
};

}  // namespace

// A coarse remeshing (edges 3 long) of the bordered grid's region: kept at their indices, the
// fixed rows' faces forbid nearly every collapse (more vertices than the 9× fewer the target
// asks for stay: about as many as it had); allowed to shrink, the region keeps under a fifth of
// its vertices, and every fixed vertex and every face outside comes back in its order, bit for bit
// (each face's fixed corners at the same positions, its movable ones movable), with the grid's
// boundary and Euler characteristic.
// At the grid's own edge length (1: splits only, the region grows) both give the same mesh.
TEST(PatchRemeshing, ARegionMayShrinkPastTheFacesAroundItKeepingTheirOrder) {
  const BorderedGrid input;
  const int movingBefore = static_cast<int>(std::count(input.movable.begin(), input.movable.end(), 1));
  BorderedGrid kept = input, shrunk = input;
  kept.remesh(3, false);
  shrunk.remesh(3, true);
  const auto movingOf = [](const BorderedGrid& g) {
    return static_cast<int>(std::count(g.movable.begin(), g.movable.end(), 1));
  };
  EXPECT_GT(movingOf(kept), movingBefore / 2);
  EXPECT_LT(movingOf(shrunk), movingBefore / 5);
  const std::vector<Vec3> fixedBefore = input.fixedPositions(), fixedAfter = shrunk.fixedPositions();
  ASSERT_EQ(fixedAfter.size(), fixedBefore.size());
  for (std::size_t k = 0; k < fixedBefore.size(); ++k) EXPECT_TRUE(test::bitEqual(fixedAfter[k], fixedBefore[k])) << k;
  const auto outsideBefore = input.outsideFaces(), outsideAfter = shrunk.outsideFaces();
  ASSERT_EQ(outsideAfter.size(), outsideBefore.size());
  for (std::size_t k = 0; k < outsideBefore.size(); ++k)
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(test::bitEqual(outsideAfter[k][c], outsideBefore[k][c])) << k;
  EXPECT_EQ(shrunk.region.size(), shrunk.mesh.faces.size());
  const Topology t0(input.mesh.vertexCount(), input.mesh.faces), t1(shrunk.mesh.vertexCount(), shrunk.mesh.faces);
  EXPECT_EQ(t1.inconsistentEdgeCount(), 0);
  EXPECT_EQ(t1.nonManifoldVertexCount(), 0);
  EXPECT_EQ(t1.boundaryEdgeCount(), t0.boundaryEdgeCount());
  EXPECT_EQ(t1.eulerCharacteristic(), t0.eulerCharacteristic());

  BorderedGrid fine = input, fineShrinking = input;
  fine.remesh(1, false);
  fineShrinking.remesh(1, true);
  EXPECT_EQ(fineShrinking.mesh.faces, fine.mesh.faces);
  EXPECT_EQ(fineShrinking.region, fine.region);
  ASSERT_EQ(fineShrinking.mesh.vertexCount(), fine.mesh.vertexCount());
  for (int v = 0; v < fine.mesh.vertexCount(); ++v)
    EXPECT_TRUE(test::bitEqual(fineShrinking.mesh.positions[v], fine.mesh.positions[v])) << v;
}
