// SPDX-License-Identifier: GPL-3.0-or-later
#include "filter_elastica_2020.h"
#include "filter_common.h"
#include "view_shading.h"

namespace em = elastica::meshlab;

FilterElasticaPlugin::FilterElasticaPlugin() {
  for (elastica::app::FilterId id : em::filterIds()) {
    typeList << static_cast<FilterIDType>(id);
    actionList << new QAction(em::filterName(id), this);
  }
}

FilterElasticaPlugin::~FilterElasticaPlugin() = default;  // the actions are children of this QObject

QString FilterElasticaPlugin::pluginName() const { return "FilterElastica"; }

QString FilterElasticaPlugin::filterName(FilterIDType filter) const { return em::filterName(em::filterId(filter)); }

QString FilterElasticaPlugin::filterInfo(FilterIDType filter) const { return em::filterInfo(em::filterId(filter)); }

MeshFilterInterface::FilterClass FilterElasticaPlugin::getClass(QAction* action) {
  return em::filterClass(em::filterId(ID(action)));
}

int FilterElasticaPlugin::getRequirements(QAction*) { return MeshModel::MM_NONE; }

int FilterElasticaPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

// MeshLab 2020.09 asks for the post-condition twice: when the dialog opens (a mask without vertex
// or face numbers makes the filter previewable: rerun at every change of a parameter, with only
// the masked attributes saved for undoing it) and after applyFilter (the attributes whose render
// buffers it refreshes and whose display it turns on, even after a failed run). So the dialog gets
// the declared mask and the refresh gets what the run changed: a failed run, or a fill without
// holes, changes nothing, and quality and colour count only when the run wrote them. (MeshLab
// 2022.02 made this the applyFilter's postConditionMask out-parameter: filter_elastica_2022.cpp.)
int FilterElasticaPlugin::postCondition(QAction* action) const {
  const elastica::app::FilterId id = em::filterId(ID(action));
  if (const std::optional<int>& ran = lastRunMask_[static_cast<size_t>(id)]) return *ran;
  return em::declaredChanges(id);
}

MeshFilterInterface::FILTER_ARITY FilterElasticaPlugin::filterArity(QAction*) const { return SINGLE_MESH; }

void FilterElasticaPlugin::initParameterSet(QAction* action, MeshModel& m, RichParameterList& params) {
  lastRunMask_[static_cast<size_t>(ID(action))].reset();  // a dialog opens: postCondition declares
  em::addParameters(em::filterId(ID(action)), m.cm, params);
}

bool FilterElasticaPlugin::applyFilter(QAction* action, MeshDocument& md, const RichParameterList& params,
                                       vcg::CallBackPos* cb) {
  const elastica::app::FilterId id = em::filterId(ID(action));
  std::optional<int>& runMask = lastRunMask_[static_cast<size_t>(id)];
  runMask = int(MeshModel::MM_NONE);  // until it succeeds
  try {
    const em::RunOutcome outcome = em::runFilter(id, md, params, cb);
    runMask = em::keepUserShading(outcome.changed, md);  // the user's shading stays (view_shading.h)
    for (const em::LogLine& line : outcome.log) {
      if (line.warning)
        Log(GLLogStream::WARNING, "%s", line.text.c_str());
      else
        Log("%s", line.text.c_str());
    }
    return true;
  } catch (...) {
    errorMessage = em::qs(em::failureMessage(id));
  }
  Log(GLLogStream::WARNING, qUtf8Printable(errorMessage));
  return false;
}
