// SPDX-License-Identifier: GPL-3.0-or-later
// The plugin class in process, on MeshLab's own MeshDocument/CMeshO (libmeshlab-common): defaults
// that follow the mesh, and failures that leave the mesh exactly as it was, with the message in
// errorMessage and in the log (meshlabserver prints only the log).
#include "filter_elastica_2020.h"

#include <elastica/shapes.h>
#include <elastica/app/filter_run.h>
#include <elastica/app/filter_apply.h>
#include <elastica/app/filter_spec.h>
#include <elastica/geometry.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/mesh_curvature.h>
#include <elastica/vcg_adapter.h>

#include <gtest/gtest.h>

#include <QTextDocument>

#include <algorithm>
#include <cmath>
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

// Fairing and curvature under Smoothing, Fairing and Deformation; hole filling under Remeshing,
// beside MeshLab's Close Holes.
TEST_F(PluginFilter, FiltersAreInTheirMenus) {
  QStringList names;
  for (QAction* a : plugin.actions()) names << a->text();
  EXPECT_TRUE(names.contains("Discrete Elastica Fairing"));
  EXPECT_TRUE(names.contains("Fill Holes with Discrete Elastica"));
  EXPECT_TRUE(names.contains("Discrete Elastica Curvature"));
  EXPECT_EQ(int(plugin.getClass(action("Discrete Elastica Fairing"))), int(MeshFilterInterface::Smoothing));
  EXPECT_EQ(int(plugin.getClass(action("Fill Holes with Discrete Elastica"))), int(MeshFilterInterface::Remeshing));
  EXPECT_EQ(int(plugin.getClass(action("Discrete Elastica Curvature"))),
            int(MeshFilterInterface::Smoothing | MeshFilterInterface::Normal));
}

// The dialogs are the options table's rows with an .mlx name (app/filter_spec.h), in the table's
// order, each with its type, label, tooltip and default (and, for a RichEnum, the table's menu).
TEST_F(PluginFilter, DialogIsTheTablesMeshLabRows) {
  fill(mm->cm, elastica::shapes::icosphere(1.0, 1));
  namespace ea = elastica::app;
  for (const ea::FilterSpec& spec : ea::allFilters(ea::meshFacts(mm->cm))) {
    const RichParameterList params = defaults(QString::fromStdString(spec.name));
    std::vector<std::string> names;
    for (const RichParameter& p : params) names.push_back(p.name().toStdString());
    std::vector<std::string> rows;
    for (const ea::ParamSpec& row : spec.params)
      if (row.inMeshLab()) rows.push_back(row.name);
    EXPECT_EQ(names, rows) << spec.name;
    for (const ea::ParamSpec& row : spec.params) {
      if (!row.inMeshLab()) continue;
      SCOPED_TRACE(spec.name + " / " + row.name);
      const QString name = QString::fromStdString(row.name);
      const RichParameter& p = params.getParameterByName(name);
      EXPECT_EQ(p.fieldDescription().toStdString(), row.label);
      EXPECT_EQ(p.toolTip().toStdString(), row.tooltip);
      switch (row.type) {
        case ea::ParamType::Bool: EXPECT_EQ(params.getBool(name), row.defaultValue != 0); break;
        case ea::ParamType::Int: EXPECT_EQ(params.getInt(name), int(row.defaultValue)); break;
        case ea::ParamType::Float: EXPECT_EQ(params.getFloat(name), float(row.defaultValue)); break;
        case ea::ParamType::AbsPerc: EXPECT_EQ(params.getAbsPerc(name), float(row.defaultValue)); break;
        case ea::ParamType::Enum: {
          EXPECT_EQ(params.getEnum(name), int(row.defaultValue));
          QStringList menu;
          for (const std::string& e : row.enumValues) menu << QString::fromStdString(e);
          EXPECT_EQ(dynamic_cast<const RichEnum&>(p).enumvalues, menu);
          break;
        }
      }
    }
  }
}

// Every help string as MeshLab shows it: a parameter's help under its field is Qt rich text
// ("<small>" + tooltip + "</small>", ml_std_par_dialog / richparameterwidgets.cpp) and its tooltip
// auto-detected, so labels and tooltips carry no markup characters and read back unchanged; the
// filter's description is HTML ("<i>" + info + "</i>") and must leave no tag text behind (a raw
// "H^2 < K ... >= 0.5" once swallowed everything between them).
TEST_F(PluginFilter, HelpTextsReadTheSameAsRichText) {
  fill(mm->cm, elastica::shapes::icosphere(1.0, 1));
  const auto rendered = [](const QString& html) {
    QTextDocument d;
    d.setHtml(html);
    return d.toPlainText().simplified();
  };
  int strings = 0;
  for (QAction* a : plugin.actions()) {
    const std::string filter = a->text().toStdString();
    RichParameterList params;
    plugin.initParameterSet(a, doc, params);
    ASSERT_FALSE(params.isEmpty()) << filter;
    for (const RichParameter& p : params) {
      for (const QString& text : {p.fieldDescription(), p.toolTip()}) {
        EXPECT_FALSE(text.contains('<') || text.contains('>') || text.contains('&'))
            << filter << " / " << p.name().toStdString() << ": " << text.toStdString();
        EXPECT_EQ(rendered("<small>" + text + "</small>"), text.simplified()) << filter << " / " << p.name().toStdString();
        EXPECT_FALSE(text.isEmpty()) << filter << " / " << p.name().toStdString();
        ++strings;
      }
    }
    const QString info = rendered("<i>" + plugin.filterInfo(plugin.ID(a)) + "</i>");
    EXPECT_FALSE(info.contains('<') || info.contains('>')) << filter << ": " << info.toStdString();
    EXPECT_TRUE(info.endsWith("Geometric Modeling and Processing 2002, pp. 119-123.")) << info.toStdString();
    ++strings;
  }
  EXPECT_EQ(strings, 2 * (11 + 7 + 2) + 3);  // fairing, fill and curvature parameters; 3 descriptions
}

// The time limit: a parameter of every flow filter (60 s by default); reaching it keeps the mesh
// as the flow left it and logs a warning that names the dialog's field. Progress meanwhile moves
// forward, never back, and stays below MeshLab's "done".
TEST_F(PluginFilter, TimeLimitStopsWithAWarningAndProgressMoves) {
  EXPECT_FLOAT_EQ(defaults("Discrete Elastica Fairing").getFloat("maxSeconds"), 60.f);
  EXPECT_FLOAT_EQ(defaults("Fill Holes with Discrete Elastica").getFloat("maxSeconds"), 60.f);
  fillNoisySphere();
  const Snapshot before = snapshot(mm->cm);
  RichParameterList params = defaults("Discrete Elastica Fairing");
  params.setValue("scheme", EnumValue(0));  // explicit: runs far past a short limit
  params.setValue("featureSize", AbsPercValue(0.f));  // to the limit shape
  params.setValue("energyTolerance", FloatValue(0.f));
  params.setValue("maxSeconds", FloatValue(1.f));
  static std::vector<int> percents;
  percents.clear();
  vcg::CallBackPos* record = [](const int pos, const char*) {
    percents.push_back(pos);
    return true;
  };
  ASSERT_TRUE(plugin.applyFilter(action("Discrete Elastica Fairing"), doc, params, record)) << plugin.errorMsg().toStdString();
  EXPECT_NE(snapshot(mm->cm).coords, before.coords);
  QStringList warnings;
  for (const auto& [level, text] : log.logStringList())
    if (level == GLLogStream::WARNING) warnings << text;
  ASSERT_EQ(warnings.size(), 1) << logLines(log).join("\n").toStdString();
  EXPECT_TRUE(warnings[0].contains("stopped at the time limit of 1 s")) << warnings[0].toStdString();
  EXPECT_TRUE(warnings[0].contains("raise 'Time limit (s)' (maxSeconds)")) << warnings[0].toStdString();
  // The wiring only: how far each report gets depends on the machine's speed and load, which
  // FlowProgress.TimeStepsAndStages covers with an injected clock.
  ASSERT_GE(percents.size(), 2u);
  EXPECT_TRUE(std::is_sorted(percents.begin(), percents.end()));
  EXPECT_LT(percents.front(), percents.back());
  EXPECT_LE(percents.back(), 99);
}

// The progress function alone: the share of the time limit, of the steps and of the stages.
TEST(FlowProgress, TimeStepsAndStages) {
  std::vector<int> seen;
  elastica::FlowOptions o;
  o.maxSeconds = 0.4;
  o.maxSteps = 1000;
  o.subdivisionLevels = 1;
  double clock = 0;  // an injected clock: the expectations hold on any machine, however loaded
  const auto progress = elastica::app::flowProgress(
      [&](int percent, const std::string&) {
        seen.push_back(percent);
        return true;
      },
      o, [&] { return clock; });
  elastica::FlowProgress p;
  progress(p);
  clock += 0.2;
  progress(p);
  p.level = 1;  // the second of two stages begun
  progress(p);
  p.level = 0;
  p.step = 900;
  progress(p);
  clock += 0.4;
  progress(p);
  ASSERT_EQ(seen.size(), 5u);
  EXPECT_EQ(seen[0], 0);
  EXPECT_EQ(seen[1], 50);
  EXPECT_GE(seen[2], 50);
  EXPECT_EQ(seen[3], 90);
  EXPECT_EQ(seen[4], 99);  // capped: 100 is MeshLab's "done"
  EXPECT_TRUE(elastica::app::flowProgress({}, o) == nullptr);
}

// The post-condition says what the run changed, so MeshLab refreshes (and turns on the display
// of) only that: before a run the declared mask (fairing and filling change the connectivity, so
// no preview); after a failure nothing; quality and colour only when asked for.
TEST_F(PluginFilter, PostConditionNamesWhatTheRunChanged) {
  QAction* fairing = action("Discrete Elastica Fairing");
  QAction* curvature = action("Discrete Elastica Curvature");
  fillNoisySphere();
  RichParameterList params = defaults("Discrete Elastica Fairing");
  EXPECT_TRUE(plugin.postCondition(fairing) & MeshModel::MM_VERTNUMBER);
  EXPECT_EQ(plugin.postCondition(curvature), int(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR));
  params.setValue("maxSteps", IntValue(5));
  ASSERT_TRUE(plugin.applyFilter(fairing, doc, params, nullptr)) << plugin.errorMsg().toStdString();
  const int faired = plugin.postCondition(fairing);
  EXPECT_TRUE(faired & MeshModel::MM_VERTCOORD);
  EXPECT_TRUE(faired & MeshModel::MM_VERTNORMAL);
  EXPECT_FALSE(faired & (MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY | MeshModel::MM_FACECOLOR |
                         MeshModel::MM_FACEQUALITY | MeshModel::MM_WEDGTEXCOORD));
  params.setValue("colorByMeanCurvature", BoolValue(true));
  ASSERT_TRUE(plugin.applyFilter(fairing, doc, params, nullptr));
  EXPECT_TRUE(plugin.postCondition(fairing) & MeshModel::MM_VERTCOLOR);
  EXPECT_FALSE(plugin.postCondition(fairing) & MeshModel::MM_FACECOLOR);
  params.setValue("Selected", BoolValue(true));  // nothing selected: fails
  EXPECT_FALSE(plugin.applyFilter(fairing, doc, params, nullptr));
  EXPECT_EQ(plugin.postCondition(fairing), int(MeshModel::MM_NONE));
  defaults("Discrete Elastica Fairing");  // the dialog opens again: the declared mask
  EXPECT_TRUE(plugin.postCondition(fairing) & MeshModel::MM_VERTNUMBER);
}

// Hole filling on a closed mesh: nothing to do, said plainly; the mesh and its selection stay.
TEST_F(PluginFilter, FillOnAClosedMeshKeepsTheSelection) {
  fillNoisySphere();
  mm->cm.face[2].SetS();
  mm->cm.face[7].SetS();
  const Snapshot before = snapshot(mm->cm);
  QAction* fillHoles = action("Fill Holes with Discrete Elastica");
  ASSERT_TRUE(plugin.applyFilter(fillHoles, doc, defaults("Fill Holes with Discrete Elastica"), nullptr))
      << plugin.errorMsg().toStdString();
  EXPECT_TRUE(snapshot(mm->cm) == before);
  for (size_t f = 0; f < mm->cm.face.size(); ++f) EXPECT_EQ(mm->cm.face[f].IsS(), f == 2 || f == 7) << f;
  EXPECT_TRUE(logLines(log).join("\n").contains("the mesh has no holes: nothing to fill; the mesh and its selection are unchanged"))
      << logLines(log).join("\n").toStdString();
  EXPECT_EQ(plugin.postCondition(fillHoles), int(MeshModel::MM_NONE));
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
  params.setValue("maxSteps", IntValue(5));  // the flow to the limit shape takes ~20
  params.setValue("featureSize", AbsPercValue(0.f));
  params.setValue("colorByMeanCurvature", BoolValue(true));
  ASSERT_TRUE(plugin.applyFilter(action("Discrete Elastica Fairing"), doc, params, nullptr)) << plugin.errorMsg().toStdString();
  const Snapshot after = snapshot(mm->cm);
  EXPECT_EQ(after.faces, before.faces);
  EXPECT_NE(after.coords, before.coords);
  EXPECT_NE(after.quality, before.quality);  // H stored as quality
  EXPECT_TRUE(mm->hasDataMask(MeshModel::MM_VERTQUALITY));
  EXPECT_TRUE(logLines(log).join("\n").contains("stopped at maxSteps")) << logLines(log).join("\n").toStdString();
  EXPECT_TRUE(logLines(log).join("\n").contains("raise 'Maximum steps' (maxSteps)")) << logLines(log).join("\n").toStdString();
}

// The dialog's defaults on a real scan (the bundled Stanford bunny): OK gives a fairer surface of
// the same model, as MeshLab's own smoothing filters do, never the flow's limit shape. The
// feature size shown is the mesh's own amount (autoFeatureSize); the vertices move by at most 1 %
// of the bounding-box diagonal (RMS), the energy goes down, the run ends by itself, the log says
// how far the surface moved.
TEST_F(PluginFilter, DefaultsKeepTheModelOfAScan) {
  const elastica::TriMesh bunny = elastica::io::readMesh(std::string(ELASTICA_DATA_DIR) + "/bunny.ply").mesh;
  fill(mm->cm, bunny);
  const Snapshot before = snapshot(mm->cm);
  const RichParameterList params = defaults("Discrete Elastica Fairing");
  const double amount = elastica::app::autoFeatureSize(bunny, nullptr);
  EXPECT_NEAR(params.getAbsPerc("featureSize"), amount, 1e-5 * amount);
  ASSERT_TRUE(plugin.applyFilter(action("Discrete Elastica Fairing"), doc, params, nullptr)) << plugin.errorMsg().toStdString();
  const Snapshot after = snapshot(mm->cm);
  EXPECT_EQ(after.faces, before.faces);
  double sum = 0;
  for (std::size_t i = 0; i < after.coords.size(); ++i) sum += std::pow(double(after.coords[i]) - before.coords[i], 2);
  const double rms = std::sqrt(sum / bunny.vertexCount()), diagonal = elastica::boundingBoxDiagonal(bunny.positions);
  EXPECT_GT(rms, 0);
  EXPECT_LE(rms, 0.01 * diagonal);
  const double energyAfter = elastica::measureCurvature(elastica::toTriMesh(mm->cm), {}).energy;
  EXPECT_LT(energyAfter, elastica::measureCurvature(bunny, {}).energy);
  const std::string text = logLines(log).join("\n").toStdString();
  EXPECT_NE(text.find("faired to the feature size"), std::string::npos) << text;
  EXPECT_NE(text.find("the vertices moved by"), std::string::npos) << text;
  EXPECT_EQ(text.find("warning"), std::string::npos) << text;
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
  const int changed = plugin.postCondition(action("Fill Holes with Discrete Elastica"));
  EXPECT_TRUE(changed & MeshModel::MM_FACENUMBER);
  EXPECT_TRUE(changed & MeshModel::MM_FACEFLAGSELECT);
  EXPECT_FALSE(changed & (MeshModel::MM_VERTCOLOR | MeshModel::MM_FACECOLOR | MeshModel::MM_VERTQUALITY));
}

namespace {
double faceArea(const CFaceO& f) { return double(vcg::DoubleArea(f)) / 2; }
vcg::Point3f centroid(const CFaceO& f) { return (f.cP(0) + f.cP(1) + f.cP(2)) / 3.0f; }
}  // namespace

// A selected fair at the defaults (remeshing on): afterwards the face selection is the faired
// region as remeshed, within the footprint the user selected and of about its area, and no vertex
// is selected. The log's first energy is the input's, as `elastica curvature` measures it.
TEST_F(PluginFilter, SelectedFairKeepsTheRegionSelectedAndNoVertex) {
  for (int levels : {0, 1}) {  // 1: the selection subdivided, the mesh rebuilt
    log.Clear();
    mm->cm.Clear();
    elastica::TriMesh mesh = elastica::shapes::icosphere(1.0, 3);
    elastica::shapes::addRadialNoise(mesh, 0.05, 7);
    fill(mm->cm, mesh);
    double selectedArea = 0;
    int selectedBefore = 0;
    for (auto& f : mm->cm.face)
      if (centroid(f).Normalize().Z() > 0.3f) {
        f.SetS();
        selectedArea += faceArea(f);
        ++selectedBefore;
      }
    const double inputEnergy = elastica::measureCurvature(elastica::toTriMesh(mm->cm), {}).energy;
    RichParameterList params = defaults("Discrete Elastica Fairing");
    ASSERT_TRUE(params.getBool("Selected"));
    params.setValue("subdivisionLevels", IntValue(levels));
    if (levels > 0) params.setValue("featureSize", AbsPercValue(0.f));  // coarse to fine goes to the limit shape
    ASSERT_TRUE(plugin.applyFilter(action("Discrete Elastica Fairing"), doc, params, nullptr)) << plugin.errorMsg().toStdString();
    const std::string text = logLines(log).join("\n").toStdString();
    double areaAfter = 0;
    int selectedAfter = 0;
    for (const auto& f : mm->cm.face) {
      if (f.IsD()) continue;
      const float z = centroid(f).Normalize().Z();
      if (f.IsS()) {
        ++selectedAfter;
        areaAfter += faceArea(f);
        EXPECT_GT(z, 0.2f) << levels;  // inside the footprint selected (its edge: the selected faces' centroids)
      } else {
        EXPECT_LT(z, 0.4f) << levels;
      }
    }
    for (const auto& v : mm->cm.vert) EXPECT_FALSE(!v.IsD() && v.IsS()) << levels << ": a vertex is left selected";
    std::printf("levels %d: selected faces %d -> %d, area %.4f -> %.4f\n", levels, selectedBefore, selectedAfter,
                selectedArea, areaAfter);
    if (levels == 1) {  // the region refined, and all of it selected
      EXPECT_GT(selectedAfter, 3 * selectedBefore);
    }
    EXPECT_NEAR(areaAfter, selectedArea, 0.15 * selectedArea) << levels;  // the noise's wrinkles faired away
    char expected[64];
    std::snprintf(expected, sizeof expected, "total curvature energy %.9g -> ", inputEnergy);
    EXPECT_NE(text.find(expected), std::string::npos) << expected << "\n" << text;
  }
}

// The Bilaplacian flow with the dialog's default scheme (Automatic) runs, explicitly, on a mesh
// with a handle too (where Automatic picks Semi-implicit for the elastica flow); the default
// maximum steps is 0, no limit.
TEST_F(PluginFilter, BilaplacianRunsWithTheDefaultSchemeAndNoStepLimit) {
  fill(mm->cm, elastica::shapes::torus(3, 1, 8, 4));
  RichParameterList params = defaults("Discrete Elastica Fairing");
  EXPECT_EQ(params.getInt("maxSteps"), 0);
  params.setValue("flow", EnumValue(2));
  ASSERT_TRUE(plugin.applyFilter(action("Discrete Elastica Fairing"), doc, params, nullptr)) << plugin.errorMsg().toStdString();
  const std::string text = logLines(log).join("\n").toStdString();
  EXPECT_EQ(text.find("stopped at maxSteps"), std::string::npos) << text;
}
