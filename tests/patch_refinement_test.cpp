// SPDX-License-Identifier: GPL-3.0-or-later
// Refining a hole's triangulation to the density around it (restoration/patch_refinement, Liepa
// 2003 §4): centroid splits where a triangle is too large for the edge lengths at its corners,
// Delaunay flips inside the patch only.
#include "hole_patches.h"
#include "test_meshes.h"

#include <elastica/geometry.h>
#include <elastica/hole_filling.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>
#include "restoration/patch_refinement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

using namespace elastica;

namespace {

// A 12×12 grid of unit squares with the 6×6 square in its middle cut away and triangulated: 24
// border edges of length 1, 22 long thin triangles, no interior vertex.
test::PatchedHole squareHole() {
  const TriMesh cut = test::cutAway(shapes::grid(12, 12, 1.0), [](const Vec3& c) {
    return c.x() > 3 && c.x() < 9 && c.y() > 3 && c.y() < 9;
  });
  return test::triangulateSmallestHole(cut).value();
}

double area(const TriMesh& m, const Face& f) {
  return 0.5 * (m.positions[f[1]] - m.positions[f[0]]).cross(m.positions[f[2]] - m.positions[f[0]]).norm();
}

}  // namespace

// Refining the flat square hole with the local edge length σ = 1 everywhere:
// - Liepa's stopping rule holds on every patch face (no face is left with α|c − v| above both σ_v
//   and the centroid's σ at all three corners, α = √2);
// - the triangles are about as large as the grid's (whose edges are 1 and √2): every patch edge
//   between σ/2 and 2σ, and their mean within 20 % of σ;
// - the patch stays flat (z = 0 exactly: split points are centroids of flat triangles), tiles the
//   hole's 36 units of area exactly (to 1e-12) without a fold (every normal +z), is Delaunay inside
//   (the two angles opposite an inner edge sum to at most π + 1e-9) and closes the hole (the only
//   boundary left is the grid's rim; Euler characteristic 1);
// - nothing outside changes: original vertices bit for bit, every face outside the patch as it was.
TEST(PatchRefinement, BringsTheFlatPatchToTheSurroundingDensity) {
  test::PatchedHole h = squareHole();
  ASSERT_EQ(h.mesh.faceCount() - h.firstPatchFace, 22);
  const TriMesh before = h.mesh;
  std::vector<double> sigma(h.mesh.positions.size(), 1.0);
  const PatchRefinementOptions opt;
  refinePatch(h.mesh, h.patchFace, sigma, opt);
  const TriMesh& m = h.mesh;

  ASSERT_EQ(sigma.size(), m.positions.size());
  ASSERT_EQ(h.patchFace.size(), m.faces.size());
  EXPECT_GT(m.vertexCount(), h.firstNew + 15);  // the 36 unit squares' worth of interior vertices
  for (int v = 0; v < h.firstNew; ++v)
    EXPECT_EQ(std::memcmp(m.positions[v].data(), before.positions[v].data(), sizeof(Vec3)), 0) << v;
  for (int f = 0; f < h.firstPatchFace; ++f) {
    EXPECT_FALSE(h.patchFace[f]);
    EXPECT_EQ(m.faces[f], before.faces[f]) << f;
  }
  for (int v = h.firstNew; v < m.vertexCount(); ++v) {
    EXPECT_EQ(m.positions[v].z(), 0.0) << v;
    EXPECT_EQ(sigma[v], 1.0) << v;
  }

  double patchArea = 0;
  for (int f = 0; f < m.faceCount(); ++f) {
    if (!h.patchFace[f]) continue;
    const Face& t = m.faces[f];
    patchArea += area(m, t);
    const Vec3 n = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    EXPECT_GT(n.z(), 0) << "face " << f;
    const Vec3 c = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0;
    const double sc = (sigma[t[0]] + sigma[t[1]] + sigma[t[2]]) / 3.0;
    bool tooLarge = true;
    for (int v : t) {
      const double d = opt.density * (c - m.positions[v]).norm();
      tooLarge = tooLarge && d > sc && d > sigma[v];
    }
    EXPECT_FALSE(tooLarge) << "face " << f;
  }
  EXPECT_NEAR(patchArea, 36.0, 1e-12);

  const Topology topo(m.vertexCount(), m.faces);  // throws on a non-manifold edge
  EXPECT_EQ(topo.inconsistentEdgeCount(), 0);
  EXPECT_EQ(topo.boundaryEdgeCount(), 4 * 12);
  EXPECT_EQ(topo.eulerCharacteristic(), 1);
  const Geometry g = computeGeometry(topo, m.positions);
  double sum = 0;
  int edges = 0;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& oc = topo.edgeOppositeCorners(e);
    const bool inner = oc[1] >= 0 && h.patchFace[oc[0] / 3] && h.patchFace[oc[1] / 3];
    const bool border = oc[1] >= 0 && h.patchFace[oc[0] / 3] != h.patchFace[oc[1] / 3];
    if (!inner && !border) continue;
    const auto& ev = topo.edgeVertices(e);
    const double len = (m.positions[ev[0]] - m.positions[ev[1]]).norm();
    EXPECT_GE(len, 0.5) << "edge " << e;
    EXPECT_LE(len, 2.0) << "edge " << e;
    sum += len;
    ++edges;
    if (inner) { EXPECT_LE(g.cornerAngle(oc[0]) + g.cornerAngle(oc[1]), M_PI + 1e-9) << "edge " << e; }
  }
  EXPECT_NEAR(sum / edges, 1.0, 0.2);
}

// The density follows σ: halving σ (the surrounding edges half as long) gives about four times the
// triangles, as Liepa's rule compares lengths (between 3× and 5×: the border's edges stay 1 long).
TEST(PatchRefinement, DensityFollowsTheLocalEdgeLength) {
  auto patchFaces = [](double s) {
    test::PatchedHole h = squareHole();
    std::vector<double> sigma(h.mesh.positions.size(), s);
    refinePatch(h.mesh, h.patchFace, sigma);
    int n = 0;
    for (std::uint8_t f : h.patchFace) n += f;
    return n;
  };
  const int coarse = patchFaces(1.0), fine = patchFaces(0.5);
  EXPECT_GT(fine, 3 * coarse);
  EXPECT_LT(fine, 5 * coarse);
}
