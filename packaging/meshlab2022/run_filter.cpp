// SPDX-License-Identifier: GPL-3.0-or-later
// run_filter: an .mlx script applied in MeshLab 2022.02 (and later, same interface) as MeshLab itself
// applies it, without MeshLab's window (2022.02 has no meshlabserver). Built and run in the trixie root
// by scripts/meshlab2022.sh.
//
//   run_filter PLUGIN_DIR[:PLUGIN_DIR...] IN OUT SCRIPT.mlx [REFERENCE TOLERANCE [--measure]]
//
// - Loads every plugin of each PLUGIN_DIR (MeshLab's plugin folder, and its per-user folder of plugins
//   added with Load Plugins) with MeshLab's own PluginManager, which checks each plugin's MeshLab
//   version and precision and throws on any it refuses.
// - Opens IN and saves OUT with MeshLab's I/O plugins (meshlab::loadMeshWithStandardParameters,
//   saveMeshWithStandardParameters).
// - Reads SCRIPT with MeshLab's FilterScript and applies each filter as MainWindow::runFilterScript
//   does: the filter's action from the PluginManager, its requirements, its log, applyFilter.
// - Prints the filters' log. With REFERENCE (e.g. `elastica run`'s output on the same script and
//   input): exit 1 unless OUT has the same vertex and face counts and faces, and every vertex is
//   within TOLERANCE (a fraction of the bounding-box diagonal) of REFERENCE's, and some vertex moved
//   from IN (prints both distances). With --measure (a script that only measures, as the curvature
//   filter): no vertex may move, REFERENCE must have a per-vertex quality, and every vertex's quality
//   must be within TOLERANCE of the largest |quality| of REFERENCE's (colours that differ are counted).
#include <common/filterscript.h>
#include <common/globals.h>
#include <common/ml_document/mesh_document.h>
#include <common/mlexception.h>
#include <common/plugins/interfaces/filter_plugin.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

#include <QApplication>
#include <QDir>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void printLog(MeshDocument& md) {
  for (const auto& line : md.Log.logStringList()) std::printf("  log: %s\n", qUtf8Printable(line.second));
  md.Log.clear();
}

MeshModel* load(MeshDocument& md, const char* file) {
  auto meshes = meshlab::loadMeshWithStandardParameters(QString::fromLocal8Bit(file), md);
  if (meshes.size() != 1) throw MLException(QString("expected one mesh in ") + file);
  return meshes.front();
}

// Largest distance between corresponding vertices over the diagonal of a's bounding box; -1 when
// the meshes differ in counts or faces.
double distance(const CMeshO& a, const CMeshO& b) {
  if (a.vn != b.vn || a.fn != b.fn || a.vert.size() != b.vert.size() || a.face.size() != b.face.size()) return -1;
  for (size_t f = 0; f < a.face.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (vcg::tri::Index(a, a.face[f].cV(k)) != vcg::tri::Index(b, b.face[f].cV(k))) return -1;
  double d = 0;
  for (size_t v = 0; v < a.vert.size(); ++v) d = std::max(d, double(vcg::Distance(a.vert[v].cP(), b.vert[v].cP())));
  return d / double(a.bbox.Diag());
}

// Per-vertex quality (the curvature filter's H) of b against a's, over a's largest |quality|. CMeshO's
// quality and colour are not optional (vector_ocf's IsQualityEnabled() is always false for them):
// whether the reference file had a quality is its MeshModel's data mask, set by the PLY reader.
bool qualityAgrees(const MeshModel& reference, const CMeshO& b, double tolerance) {
  const CMeshO& a = reference.cm;
  if (!reference.hasDataMask(MeshModel::MM_VERTQUALITY)) {
    std::printf("FAIL: the reference has no per-vertex quality\n");
    return false;
  }
  double scale = 0, d = 0;
  size_t colours = 0;
  for (size_t v = 0; v < a.vert.size(); ++v) {
    scale = std::max(scale, std::abs(double(a.vert[v].cQ())));
    d = std::max(d, std::abs(double(a.vert[v].cQ()) - double(b.vert[v].cQ())));
    colours += a.vert[v].cC() != b.vert[v].cC();
  }
  std::printf("quality vs the reference: %.2e of its largest |quality| %.3g (tolerance %.0e); colour: %zu of %zu vertices differ\n",
              d / scale, scale, tolerance, colours, a.vert.size());
  return scale > 0 && d <= tolerance * scale;
}

}  // namespace

int main(int argc, char** argv) {
  const bool measure = argc == 8 && std::string(argv[7]) == "--measure";
  if (argc != 5 && argc != 7 && !measure) {
    std::fprintf(stderr, "usage: run_filter PLUGIN_DIR[:PLUGIN_DIR...] IN OUT SCRIPT.mlx [REFERENCE TOLERANCE [--measure]]\n");
    return 2;
  }
  QApplication app(argc, argv);
  try {
    std::printf("MeshLab %s (libmeshlab-common), plugins from %s\n", meshlab::meshlabVersion().c_str(), argv[1]);
    PluginManager& pm = meshlab::pluginManagerInstance();
    for (const QString& dir : QString::fromLocal8Bit(argv[1]).split(':'))
      pm.loadPlugins(QDir(dir));   // throws if MeshLab refuses any plugin there

    MeshDocument md;
    load(md, argv[2]);
    FilterScript script;
    if (!script.open(QString::fromLocal8Bit(argv[4]))) throw MLException(QString("cannot read the script ") + argv[4]);
    for (FilterNameParameterValuesPair& pair : script) {
      QAction* action = pm.filterAction(pair.filterName());
      if (!action) throw MLException("no loaded plugin has the filter " + pair.filterName());
      FilterPlugin* filter = pm.getFilterPluginFromAction(action);
      std::printf("%s (plugin %s)\n", qUtf8Printable(pair.filterName()), qUtf8Printable(filter->pluginName()));
      md.mm()->updateDataMask(filter->getRequirements(action));
      filter->setLog(&md.Log);
      unsigned int postConditionMask = MeshModel::MM_UNKNOWN;
      filter->applyFilter(action, pair.second, md, postConditionMask, nullptr);
      vcg::tri::Allocator<CMeshO>::CompactEveryVector(md.mm()->cm);
      printLog(md);
    }
    md.mm()->cm.bbox.SetNull();
    vcg::tri::UpdateBounding<CMeshO>::Box(md.mm()->cm);
    meshlab::saveMeshWithStandardParameters(QString::fromLocal8Bit(argv[3]), *md.mm());
    std::printf("wrote %s: %d vertices, %d faces\n", argv[3], md.mm()->cm.vn, md.mm()->cm.fn);

    if (argc >= 7) {
      MeshDocument in, ref;
      const CMeshO& input = load(in, argv[2])->cm;
      const MeshModel& referenceModel = *load(ref, argv[5]);
      const CMeshO& reference = referenceModel.cm;
      const double tolerance = std::atof(argv[6]);
      const double same = distance(reference, md.mm()->cm);
      if (same < 0) {
        std::printf("FAIL: %s has %d vertices, %d faces, %s %d and %d (or other faces)\n", argv[3], md.mm()->cm.vn,
                    md.mm()->cm.fn, argv[5], reference.vn, reference.fn);
        return 1;
      }
      // Moved: the input's vertices (a fill appends new ones after them) against the output's first ones.
      double moved = 0;
      for (size_t v = 0; v < input.vert.size() && v < md.mm()->cm.vert.size(); ++v)
        moved = std::max(moved, double(vcg::Distance(input.vert[v].cP(), md.mm()->cm.vert[v].cP())));
      moved /= double(reference.bbox.Diag());
      const bool grew = md.mm()->cm.vn != input.vn;
      std::printf("vs %s: %.2e of the diagonal (tolerance %.0e); vs the input: %s\n", argv[5], same, tolerance,
                  grew ? qUtf8Printable(QString("%1 -> %2 vertices").arg(input.vn).arg(md.mm()->cm.vn))
                       : qUtf8Printable(QString("moved %1 of the diagonal").arg(moved, 0, 'e', 2)));
      if (measure) return qualityAgrees(referenceModel, md.mm()->cm, tolerance) && moved == 0 && same <= tolerance ? 0 : 1;
      if (!(same <= tolerance) || (!grew && moved < 1e-3)) {
        std::printf("FAIL\n");
        return 1;
      }
    }
    return 0;
  } catch (const MLException& e) {
    std::fprintf(stderr, "run_filter: %s\n", e.what());
    return 1;
  }
}
