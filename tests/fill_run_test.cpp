// SPDX-License-Identifier: GPL-3.0-or-later
// The fill through the application layer (app/filter_run.h), the path of the MeshLab filter,
// `elastica run` and the Python module: it checks the input and fills on pieces of the mesh, and
// never builds a Topology of the whole mesh (several times the mesh's memory on a large scan).
#include <elastica/app/filter_run.h>
#include <elastica/app/filter_spec.h>
#include <elastica/errors.h>
#include <elastica/hole_filling.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace elastica::app {
namespace {

// An icosphere of 10,242 vertices with the faces near its north pole removed: one hole of a few
// dozen border edges.
TriMesh sphereWithAHole() {
  TriMesh m = shapes::icosphere(1.0, 5);
  std::vector<Face> kept;
  for (const Face& t : m.faces) {
    const double z = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]).z() / 3;
    if (z < 0.97) kept.push_back(t);
  }
  m.faces = kept;
  return m;
}

TEST(FillRun, FilterPathBuildsNoWholeMeshTopology) {
  const TriMesh mesh = sphereWithAHole();
  Topology::resetLargestBuilt();
  const FillHolesResult r = runFillHoles(mesh, ParamValues::defaults(filterSpec(FilterId::FillHoles, {})), {});
  ASSERT_EQ(r.report.holes.size(), 1u);
  EXPECT_EQ(r.report.filledCount(), 1);
  EXPECT_GT(r.report.holes[0].newVertices, 0);
  // The patches' flows build Topologies of their pieces (a few hundred vertices here).
  EXPECT_GT(Topology::largestBuilt(), 0);
  EXPECT_LT(Topology::largestBuilt(), mesh.vertexCount() / 10);
}

TEST(FillRun, PythonPathBuildsNoWholeMeshTopology) {
  TriMesh mesh = sphereWithAHole();
  const int vertices = mesh.vertexCount();
  Topology::resetLargestBuilt();
  checkFillInput(mesh, RepairHints::None);
  const FillHolesResult r = runFillHoles(std::move(mesh), HoleFillOptions{});
  EXPECT_EQ(r.report.filledCount(), 1);
  EXPECT_LT(Topology::largestBuilt(), vertices / 10);
}

TEST(FillRun, InputDefectsAreCountedAsTopologyCountsThem) {
  std::vector<TriMesh> meshes;
  TriMesh flipped = shapes::icosphere(1.0, 2);
  std::swap(flipped.faces[5][0], flipped.faces[5][1]);  // its three edges now run one way twice
  meshes.push_back(flipped);
  TriMesh bowTies = shapes::grid(4, 4);  // two corner-sharing copies: a bow-tie at the shared vertex
  const int n = bowTies.vertexCount();
  const std::vector<Face> first = bowTies.faces;
  for (const Face& t : first) bowTies.faces.push_back({t[0] == 0 ? 0 : t[0] + n, t[1] == 0 ? 0 : t[1] + n, t[2] == 0 ? 0 : t[2] + n});
  bowTies.positions.insert(bowTies.positions.end(), bowTies.positions.begin(), bowTies.positions.end());
  for (int v = n; v < 2 * n; ++v) bowTies.positions[v].z() += 1;
  meshes.push_back(bowTies);
  meshes.push_back(sphereWithAHole());
  meshes.push_back(shapes::torus(3, 1, 24, 12));
  for (const TriMesh& m : meshes) {
    const Topology topo(m.vertexCount(), m.faces);
    const FillInputDefects d = countFillInputDefects(m);
    EXPECT_EQ(d.inconsistentEdges, topo.inconsistentEdgeCount());
    EXPECT_EQ(d.nonManifoldVertices, topo.nonManifoldVertexCount());
  }
  EXPECT_EQ(countFillInputDefects(flipped).inconsistentEdges, 3);
  EXPECT_EQ(countFillInputDefects(bowTies).nonManifoldVertices, 1);
}

TEST(FillRun, FilterPathRejectsWhatTheFacesRefuse) {
  TriMesh flipped = sphereWithAHole();
  std::swap(flipped.faces[5][0], flipped.faces[5][1]);
  const ParamValues v = ParamValues::defaults(filterSpec(FilterId::FillHoles, {}));
  try {
    runFillHoles(flipped, v, {});
    FAIL() << "an inconsistently oriented mesh was filled";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("not consistently oriented"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Re-Orient"), std::string::npos) << e.what();
  }
  TriMesh fin = shapes::icosphere(1.0, 1);
  fin.positions.push_back(Vec3(2, 2, 2));
  fin.faces.push_back({fin.faces[0][0], fin.faces[0][1], fin.vertexCount() - 1});
  try {
    checkFillInput(fin, RepairHints::None);
    FAIL() << "a non-manifold edge was accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("non-manifold edge"), std::string::npos) << e.what();
  }
  EXPECT_THROW(checkFillInput(TriMesh{}, RepairHints::None), InvalidInputError);
}

}  // namespace
}  // namespace elastica::app
