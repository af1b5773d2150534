// SPDX-License-Identifier: GPL-3.0-or-later
#include "view_shading.h"

#if ELASTICA_MESHLAB_API >= 2022
#include <common/ml_shared_data_context/ml_scene_gl_shared_data_context.h>
#else
#include <common/ml_shared_data_context.h>
#endif

#include <QApplication>
#include <QGLWidget>

namespace elastica::meshlab {
namespace {

// True unless every view that shows `mm` shades it without vertex normals (Face shading, say).
// Views are the QGLWidgets that the document's shared GL context (MLSceneGLSharedDataContext, itself
// a QGLWidget in all three MeshLabs) holds rendering data for; without any, true.
bool someViewUsesVertexNormals(MeshDocument& md, const MeshModel& mm) {
  bool viewFound = false;
  const QWidgetList widgets = QApplication::allWidgets();
  for (QWidget* w : widgets) {
    auto* shared = qobject_cast<MLSceneGLSharedDataContext*>(w);
    if (shared == nullptr || &shared->meshDoc() != &md) continue;
    for (QWidget* v : widgets) {
      auto* view = qobject_cast<QGLWidget*>(v);
      if (view == nullptr || view == shared || view->context() == nullptr) continue;
      MLRenderingData dt;  // nothing active: a widget that is not a view of this mesh
      shared->getRenderInfoPerMeshView(mm.id(), const_cast<QGLContext*>(view->context()), dt);
      for (auto pm = MLRenderingData::PRIMITIVE_MODALITY(0); pm < MLRenderingData::PR_ARITY;
           pm = MLRenderingData::next(pm)) {
        if (!dt.isPrimitiveActive(pm)) continue;
        viewFound = true;
        MLRenderingData::RendAtts atts;
        dt.get(pm, atts);
        if (atts[MLRenderingData::ATT_NAMES::ATT_VERTNORMAL]) return true;
      }
    }
  }
  return !viewFound;
}

}  // namespace

int keepUserShading(int changed, MeshDocument& md) {
  if ((changed & MeshModel::MM_FACEVERT) || md.mm() == nullptr || someViewUsesVertexNormals(md, *md.mm()))
    return changed;
  return changed & ~int(MeshModel::MM_VERTNORMAL);
}

}  // namespace elastica::meshlab
