// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/geometry.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace elastica;

namespace {

// Signed volume by the divergence theorem: positive iff faces are oriented outward.
double signedVolume(const TriMesh& m) {
  double v = 0;
  for (const Face& f : m.faces) v += m.positions[f[0]].dot(m.positions[f[1]].cross(m.positions[f[2]])) / 6;
  return v;
}

}  // namespace

TEST(Shapes, IcosphereCountsAndVolume) {
  const TriMesh m = shapes::icosphere(2.0, 5);
  EXPECT_EQ(m.vertexCount(), 10242);
  EXPECT_NEAR(signedVolume(m), 4.0 / 3 * M_PI * 8, 0.01 * 4.0 / 3 * M_PI * 8);
}

TEST(Shapes, TorusVolume) {
  const TriMesh m = shapes::torus(3, 1, 96, 48);
  EXPECT_NEAR(signedVolume(m), 2 * M_PI * M_PI * 3, 0.01 * 2 * M_PI * M_PI * 3);
}

// The paper's tubular cage: closed, consistently and outwardly oriented, genus = windows.
TEST(Shapes, FrameCageIsAClosedSurfaceOfGenusEqualToItsWindows) {
  for (auto [wx, wy] : {std::pair{2, 1}, std::pair{1, 1}, std::pair{3, 2}}) {
    const TriMesh m = shapes::frameCage(wx, wy, 2);
    const Topology t(m.vertexCount(), m.faces);
    EXPECT_EQ(t.boundaryEdgeCount(), 0);
    EXPECT_EQ(t.inconsistentEdgeCount(), 0);
    EXPECT_EQ(t.nonManifoldVertexCount(), 0);
    EXPECT_EQ(t.eulerCharacteristic(), 2 - 2 * wx * wy);
    // Volume: (cells) unit cubes.
    const int cells = (3 * wx + 1) * (3 * wy + 1) - 4 * wx * wy;
    EXPECT_NEAR(signedVolume(m), cells, 1e-12);
  }
}
