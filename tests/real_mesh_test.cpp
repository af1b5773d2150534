// SPDX-License-Identifier: GPL-3.0-or-later
// Restoration on real meshes: the bundled bunny and CGAL's elephant (Debian's libcgal-demo, fetched by scripts/setup.sh),
// with real holes, and with a region cut away and compared with what was cut.
#include "geodesic_cut.h"
#include "surface_distance.h"
#include "test_meshes.h"
#include "self_intersections.h"

#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/geometry.h>
#include <elastica/hole_filling.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/mesh_quality.h>
#include <elastica/topology.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <gtest/gtest.h>

#include <string>

namespace elastica {
namespace {

const std::string kMeshDir = ELASTICA_SAMPLE_MESH_DIR;

TriMesh read(const std::string& name, io::ReadReport* report = nullptr) {
  VcgMesh vm;
  const io::ReadReport r = io::readMesh(kMeshDir + "/" + name, vm);
  if (report) *report = r;
  return toTriMesh(vm);
}

using test::selfIntersections;

// CGAL's hole-filling example: the elephant with 106 holes, some of whose borders pass twice
// through one point (the file stores such a vertex once per fan of faces). Filled, it must be the
// closed surface the intact elephant is, with no sliver and no self-intersection.
TEST(RealMeshes, ElephantWithHolesClosesToTheIntactElephantsTopology) {
  io::ReadReport read_report;
  TriMesh mesh = read("elephant-with-holes.off", &read_report);
  const TriMesh before = mesh;
  const TriMesh intact = read("elephant.off");
  const Topology intactTopo(intact.vertexCount(), intact.faces);
  ASSERT_EQ(intactTopo.boundaryEdgeCount(), 0);

  const HoleFillReport r = fillHoles(mesh, {});
  const std::vector<std::uint8_t> isNew = test::newFaceFlags(mesh, r);
  for (const HoleReport& h : r.holes) EXPECT_TRUE(h.filled) << h.borderEdges << " edges: " << h.reason;
  // Every point the reader found stored as two copies lies on a hole border; all holes close, so
  // every pair is welded again.
  EXPECT_GT(read_report.nonManifoldVerticesSplit, 0);
  EXPECT_EQ(static_cast<int>(r.welds.size()), read_report.nonManifoldVerticesSplit);

  const Topology topo(mesh.vertexCount(), mesh.faces);
  EXPECT_EQ(topo.boundaryEdgeCount(), 0);
  EXPECT_EQ(topo.nonManifoldVertexCount(), 0);
  EXPECT_EQ(topo.inconsistentEdgeCount(), 0);
  EXPECT_EQ(topo.eulerCharacteristic(), intactTopo.eulerCharacteristic());
  EXPECT_GE(smallestAngleDegrees(mesh, before.faceCount()), 20);
  EXPECT_EQ(selfIntersections(mesh), 0);
  // The original faces keep their corners up to the welds and the renumbering that follows them.
  for (int f = 0; f < before.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(mesh.positions[mesh.faces[f][k]], before.positions[before.faces[f][k]]) << f;
}

// The paper's experiment (Figs. 9–10) on real data: the faces whose centroids lie within `radius`
// of `center` are cut away, the hole restored, and the patch compared with what was cut.
void checkRestorationOfCut(const TriMesh& full, const Vec3& center, double radius) {
  std::vector<std::uint8_t> removed(full.faces.size(), 0), kept(full.faces.size(), 0);
  for (std::size_t f = 0; f < full.faces.size(); ++f) {
    const Face& t = full.faces[f];
    removed[f] = ((full.positions[t[0]] + full.positions[t[1]] + full.positions[t[2]]) / 3.0 - center).norm() < radius;
    kept[f] = !removed[f];
  }
  const TriMesh truth = bench::facesOf(full, removed), holed = bench::facesOf(full, kept);
  ASSERT_GT(truth.faceCount(), 100);

  auto restore = [&](FillStage stage) {
    TriMesh m = holed;
    HoleFillOptions opt;
    opt.stopAfter = stage;
    const HoleFillReport r = fillHoles(m, opt);
    EXPECT_EQ(r.filledCount(), 1);
    std::vector<std::uint8_t> isNew(m.faces.size(), 0);
    for (int f = holed.faceCount(); f < m.faceCount(); ++f) isNew[f] = 1;
    return std::make_pair(m, bench::sampledDistance(bench::facesOf(m, isNew), truth));
  };
  const auto [elastica, elasticaDistance] = restore(FillStage::Flow);
  const auto [start, startDistance] = restore(FillStage::Biharmonic);
  const auto [flat, flatDistance] = restore(FillStage::Refinement);
  std::printf("patch->truth RMS / max: elastica %.5f / %.5f, bi-Laplace %.5f / %.5f, flat %.5f / %.5f\n",
              elasticaDistance.rms, elasticaDistance.max, startDistance.rms, startDistance.max, flatDistance.rms,
              flatDistance.max);
  // The curvature flow brings the patch nearer the surface that was cut away than its start (the
  // bi-Laplace solve, CGAL's fairing), which is nearer than the flat fill.
  EXPECT_LT(elasticaDistance.rms, startDistance.rms);
  EXPECT_LT(elasticaDistance.max, startDistance.max);
  EXPECT_LT(startDistance.rms, flatDistance.rms);
  const Topology topo(elastica.vertexCount(), elastica.faces);
  EXPECT_EQ(topo.boundaryEdgeCount(), 0);
  EXPECT_EQ(topo.nonManifoldVertexCount(), 0);
  EXPECT_GE(smallestAngleDegrees(elastica, holed.faceCount()), 20);
  EXPECT_EQ(selfIntersections(elastica), 0);
}

// The bundled Stanford bunny's flank (docs/restoration.md): 215 faces, 12.7 % of the diagonal.
TEST(RealMeshes, BunnyFlankRestoredCloserThanItsBiLaplaceStart) {
  VcgMesh vm;
  io::readMesh(std::string(ELASTICA_DATA_DIR) + "/bunny.ply", vm);
  checkRestorationOfCut(toTriMesh(vm), Vec3(0.82, 2.95, 3.81), 2.0);
}

// CGAL's elephant's flank: 208 faces, 12.4 % of the diagonal.
TEST(RealMeshes, ElephantFlankRestoredCloserThanItsBiLaplaceStart) {
  checkRestorationOfCut(read("elephant.off"), Vec3(-0.084, -0.119, -0.148), 0.17);
}

// Issue 15's small holes: geodesic discs of ~18 border edges cut at spread-out places of CGAL's
// elephant (2,775 vertices; a fill of such a hole once ended at 12° with its energy 8.2 → 20.8).
// Every fill ends no worse than its bi-Laplace start (energy not higher, smallest angle not below
// min(its start's, 25°)), its report quotes the energy of the region a test can recompute from the
// output alone (the patch's faces and their vertices, each with its whole fan), and every patch
// face has 25° or what the border's sharpest corner allows.
TEST(RealMeshes, SmallHolesEndNoWorseThanTheirStart) {
  const TriMesh full = read("elephant.off");
  for (double at : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const Vec3 seed = full.positions[static_cast<std::size_t>(at * full.vertexCount())];
    const test::Cut cut = test::cutWithBorder(full, test::facesByDistance(full, seed), 18);
    TriMesh mesh = cut.holed;
    const HoleFillReport r = fillHoles(mesh, {});
    ASSERT_EQ(r.holes.size(), 1u) << at;
    const HoleReport& h = r.holes[0];
    ASSERT_TRUE(h.filled) << at;
    double startAngle = 180;
    std::string stages;  // for the failure messages
    for (const FillStageReport& s : h.stages) {
      if (s.stage == "bi-Laplace") startAngle = s.minAngleDegrees;
      stages += " " + s.stage + (s.kept ? " (kept " : " (undone ") + std::to_string(s.minAngleDegrees) + "°, E " + std::to_string(s.energy) + ")";
    }
    EXPECT_LE(h.energyAfter, h.energyBefore * (1 + 1e-4)) << at;
    EXPECT_GE(h.minAngleDegrees, std::min(startAngle, 25.0) - 1e-9) << at;
    EXPECT_GE(h.minAngleDegrees, std::min(h.borderBoundDegrees, 25.0) - 1e-9) << at << ", border bound " << h.borderBoundDegrees << ":" << stages;

    const Topology topo(mesh.vertexCount(), mesh.faces);
    const Geometry geo = computeGeometry(topo, mesh.positions);
    const Curvature curv = computeCurvature(topo, geo, mesh.positions);
    std::vector<std::uint8_t> region(mesh.positions.size(), 0);
    for (int f = r.firstNewFace; f < mesh.faceCount(); ++f)
      for (int v : mesh.faces[f]) region[v] = 1;
    EXPECT_NEAR(totalCurvatureEnergy(topo, geo, curv, &region), h.energyAfter, 1e-9 * std::abs(h.energyAfter)) << at;
    EXPECT_EQ(selfIntersections(mesh), 0) << at;
  }
}

// A start worse than the flat fill is still the shape to go on from: a 200-edge geodesic disc in
// CGAL's refined elephant (44,460 vertices) has a bi-Laplace start with a 0.3° sliver where the
// flat fill had 0.4°. The fill used to stop there and leave the flat fill (no vertex inside, E 111);
// the remeshing and the flow after it are judged against the flat fill and do far better.
TEST(RealMeshes, StartWithASliverIsStillRemeshedAndFaired) {
  const TriMesh full = read("refined_elephant.off");
  const test::Cut cut = test::cutWithBorder(full, test::facesByDistance(full, Vec3(0.0772, -0.1207, 0.2918)), 200);
  TriMesh mesh = cut.holed;
  const HoleFillReport r = fillHoles(mesh, {});
  ASSERT_EQ(r.holes.size(), 1u);
  const HoleReport& h = r.holes[0];
  ASSERT_TRUE(h.filled);
  ASSERT_FALSE(h.stages.empty());
  const FillStageReport& flat = h.stages.front();
  ASSERT_EQ(flat.stage, "triangulation");
  EXPECT_GT(mesh.vertexCount() - cut.holed.vertexCount(), 500);  // the disc's area at the scan's density
  EXPECT_LT(h.energyAfter, 0.5 * flat.energy);
  EXPECT_GE(h.minAngleDegrees, std::min(h.borderBoundDegrees, 25.0) - 1e-9);
  EXPECT_EQ(selfIntersections(mesh), 0);
}

}  // namespace
}  // namespace elastica
