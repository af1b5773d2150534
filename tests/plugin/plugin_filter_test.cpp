// The plugin class in process, on MeshLab's own MeshDocument/CMeshO (libmeshlab-common): defaults
// that follow the mesh, and failures that leave the mesh exactly as it was, with the message in
// errorMessage and in the log (meshlabserver prints only the log).
#include "filter_elastica.h"

#include <elastica/shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace {

// Fills `m` with `mesh` (float, as MeshLab stores it).
void fill(CMeshO& m, const elastica::TriMesh& mesh) {
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, mesh.positions.size());
  for (const auto& p : mesh.positions) (vi++)->P() = CMeshO::CoordType(float(p[0]), float(p[1]), float(p[2]));
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, mesh.faces.size());
  for (const auto& f : mesh.faces) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[f[k]];
    ++fi;
  }
}

// Everything a filter could change, for a bitwise comparison.
struct Snapshot {
  std::vector<float> coords;
  std::vector<int> faces;
  std::vector<float> quality;
  std::vector<unsigned> colors;
  bool operator==(const Snapshot& o) const {
    return coords == o.coords && faces == o.faces && quality == o.quality && colors == o.colors;
  }
};
Snapshot snapshot(const CMeshO& m) {
  Snapshot s;
  for (const auto& v : m.vert) {
    for (int k = 0; k < 3; ++k) s.coords.push_back(v.cP()[k]);
    s.quality.push_back(v.cQ());
    s.colors.push_back(*reinterpret_cast<const unsigned*>(&v.cC()[0]));
  }
  for (const auto& f : m.face)
    for (int k = 0; k < 3; ++k) s.faces.push_back(int(vcg::tri::Index(m, f.cV(k))));
  return s;
}

QStringList logLines(const GLLogStream& log) {
  QStringList lines;
  log.print(lines);
  return lines;
}

class PluginFilter : public ::testing::Test {
 protected:
  void SetUp() override {
    plugin.setLog(&log);
    mm = doc.addNewMesh("", "test");
  }
  QAction* action(const QString& name) { return plugin.AC(name); }
  void fillNoisySphere() {
    elastica::TriMesh mesh = elastica::shapes::icosphere(1.0, 2);
    elastica::shapes::addRadialNoise(mesh, 0.05, 7);
    fill(mm->cm, mesh);
  }
  RichParameterList defaults(const QString& name) {
    RichParameterList params;
    plugin.initParameterSet(action(name), doc, params);
    return params;
  }

  FilterElasticaPlugin plugin;
  GLLogStream log;
  MeshDocument doc;
  MeshModel* mm = nullptr;
};

}  // namespace

TEST_F(PluginFilter, FiltersAreInSmoothingClass) {
  QStringList names;
  for (QAction* a : plugin.actions()) {
    names << a->text();
    EXPECT_TRUE(plugin.getClass(a) & MeshFilterInterface::Smoothing) << a->text().toStdString();
  }
  EXPECT_TRUE(names.contains("Discrete Elastica Fairing"));
  EXPECT_TRUE(names.contains("Fill Holes with Discrete Elastica"));
  EXPECT_TRUE(names.contains("Discrete Elastica Curvature"));
}

TEST_F(PluginFilter, SelectedDefaultFollowsTheMeshSelection) {
  fill(mm->cm, elastica::shapes::icosphere(1.0, 1));
  EXPECT_FALSE(defaults("Discrete Elastica Fairing").getBool("Selected"));
  mm->cm.face[3].SetS();
  EXPECT_TRUE(defaults("Discrete Elastica Fairing").getBool("Selected"));
}

TEST_F(PluginFilter, NonManifoldEdgeFailsWithMessageAndMeshUnchanged) {
  // An icosphere with a fin: a third face on the edge (0, 1).
  elastica::TriMesh mesh = elastica::shapes::icosphere(1.0, 1);
  mesh.positions.push_back(elastica::Vec3(2, 2, 2));
  mesh.faces.push_back({mesh.faces[0][0], mesh.faces[0][1], mesh.vertexCount() - 1});
  fill(mm->cm, mesh);
  for (const QString name : {"Discrete Elastica Fairing", "Fill Holes with Discrete Elastica", "Discrete Elastica Curvature"}) {
    const Snapshot before = snapshot(mm->cm);
    const RichParameterList params = defaults(name);
    EXPECT_FALSE(plugin.applyFilter(action(name), doc, params, nullptr)) << name.toStdString();
    EXPECT_TRUE(plugin.errorMsg().contains("non-manifold edge")) << plugin.errorMsg().toStdString();
    EXPECT_TRUE(plugin.errorMsg().startsWith(name)) << plugin.errorMsg().toStdString();
    EXPECT_TRUE(logLines(log).join("\n").contains(plugin.errorMsg())) << logLines(log).join("\n").toStdString();
    EXPECT_TRUE(snapshot(mm->cm) == before) << name.toStdString();
  }
}

TEST_F(PluginFilter, InconsistentOrientationFails) {
  elastica::TriMesh mesh = elastica::shapes::icosphere(1.0, 1);
  std::swap(mesh.faces[5][0], mesh.faces[5][1]);
  fill(mm->cm, mesh);
  const Snapshot before = snapshot(mm->cm);
  EXPECT_FALSE(plugin.applyFilter(action("Discrete Elastica Fairing"), doc, defaults("Discrete Elastica Fairing"), nullptr));
  EXPECT_TRUE(plugin.errorMsg().contains("not consistently oriented")) << plugin.errorMsg().toStdString();
  EXPECT_TRUE(snapshot(mm->cm) == before);
}

// Cancelling through MeshLab's callback (returning false) fails the filter and keeps the mesh.
TEST_F(PluginFilter, CancelledByCallbackLeavesMeshUnchanged) {
  fillNoisySphere();
  const Snapshot before = snapshot(mm->cm);
  static int calls;
  calls = 0;
  vcg::CallBackPos* cancelAfterTwo = [](const int, const char*) { return ++calls < 2; };
  EXPECT_FALSE(plugin.applyFilter(action("Discrete Elastica Fairing"), doc, defaults("Discrete Elastica Fairing"),
                                  cancelAfterTwo));
  EXPECT_GE(calls, 2);
  EXPECT_TRUE(plugin.errorMsg().contains("cancelled")) << plugin.errorMsg().toStdString();
  EXPECT_TRUE(snapshot(mm->cm) == before);
}

// The positive path on CMeshO: positions move, energy goes down (the log says so), bbox updated.
TEST_F(PluginFilter, FairingMovesVerticesAndLogsEnergy) {
  fillNoisySphere();
  const Snapshot before = snapshot(mm->cm);
  RichParameterList params = defaults("Discrete Elastica Fairing");
  params.setValue("maxSteps", IntValue(5));  // the default (semi-implicit) scheme converges in ~20
  params.setValue("colorByMeanCurvature", BoolValue(true));
  ASSERT_TRUE(plugin.applyFilter(action("Discrete Elastica Fairing"), doc, params, nullptr)) << plugin.errorMsg().toStdString();
  const Snapshot after = snapshot(mm->cm);
  EXPECT_EQ(after.faces, before.faces);
  EXPECT_NE(after.coords, before.coords);
  EXPECT_NE(after.quality, before.quality);  // H stored as quality
  EXPECT_TRUE(mm->hasDataMask(MeshModel::MM_VERTQUALITY));
  EXPECT_TRUE(logLines(log).join("\n").contains("stopped at maxSteps")) << logLines(log).join("\n").toStdString();
}

// Hole filling appends: the original vertices keep their positions and colours, the new faces
// (only they) end up selected.
TEST_F(PluginFilter, FillHolesAppendsAndSelectsNewFaces) {
  elastica::TriMesh mesh = elastica::shapes::icosphere(1.0, 3);
  std::vector<elastica::Face> kept;
  for (const auto& f : mesh.faces)
    if (mesh.positions[f[0]][2] < 0.9 || mesh.positions[f[1]][2] < 0.9 || mesh.positions[f[2]][2] < 0.9) kept.push_back(f);
  ASSERT_LT(kept.size(), mesh.faces.size());
  mesh.faces = kept;  // a cap cut away: one hole; the cap's inner vertices are left unreferenced
  fill(mm->cm, mesh);
  for (auto& v : mm->cm.vert) v.C() = vcg::Color4b(10, 20, 30, 255);
  mm->cm.face[0].SetS();  // a previous selection, to be replaced
  const Snapshot before = snapshot(mm->cm);
  const RichParameterList params = defaults("Fill Holes with Discrete Elastica");
  EXPECT_TRUE(params.getBool("NewFaceSelected"));
  ASSERT_TRUE(plugin.applyFilter(action("Fill Holes with Discrete Elastica"), doc, params, nullptr))
      << plugin.errorMsg().toStdString();
  const Snapshot after = snapshot(mm->cm);
  ASSERT_GT(after.faces.size(), before.faces.size());
  EXPECT_TRUE(std::equal(before.coords.begin(), before.coords.end(), after.coords.begin()));
  EXPECT_TRUE(std::equal(before.colors.begin(), before.colors.end(), after.colors.begin()));
  EXPECT_TRUE(std::equal(before.faces.begin(), before.faces.end(), after.faces.begin()));
  for (size_t f = 0; f < mm->cm.face.size(); ++f) EXPECT_EQ(mm->cm.face[f].IsS(), f >= kept.size()) << f;
  EXPECT_TRUE(logLines(log).join("\n").contains("filled 1 of 1 holes")) << logLines(log).join("\n").toStdString();
}
