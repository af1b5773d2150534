// SPDX-License-Identifier: GPL-3.0-or-later
#include "filter_elastica_2022.h"
#include "filter_common.h"
#include "view_shading.h"

namespace em = elastica::meshlab;

FilterElasticaPlugin::FilterElasticaPlugin() {
  for (elastica::app::FilterId id : em::filterIds()) {
    typeList.push_back(static_cast<ActionIDType>(id));
    actionList.push_back(new QAction(em::filterName(id), this));
  }
}

FilterElasticaPlugin::~FilterElasticaPlugin() = default;  // the actions are children of this QObject

QString FilterElasticaPlugin::pluginName() const { return "FilterElastica"; }

QString FilterElasticaPlugin::filterName(ActionIDType filter) const { return em::filterName(em::filterId(filter)); }

QString FilterElasticaPlugin::filterInfo(ActionIDType filter) const { return em::filterInfo(em::filterId(filter)); }

FilterPlugin::FilterClass FilterElasticaPlugin::getClass(const QAction* action) const {
  return em::filterClass(em::filterId(ID(action)));
}

int FilterElasticaPlugin::getRequirements(const QAction*) { return MeshModel::MM_NONE; }

int FilterElasticaPlugin::getPreConditions(const QAction*) const { return MeshModel::MM_FACENUMBER; }

int FilterElasticaPlugin::postCondition(const QAction* action) const {
  return em::declaredChanges(em::filterId(ID(action)));
}

FilterPlugin::FilterArity FilterElasticaPlugin::filterArity(const QAction*) const { return SINGLE_MESH; }

RichParameterList FilterElasticaPlugin::initParameterList(const QAction* action, const MeshModel& m) {
  RichParameterList params;
  em::addParameters(em::filterId(ID(action)), m.cm, params);
  return params;
}

std::map<std::string, QVariant> FilterElasticaPlugin::applyFilter(const QAction* action,
                                                                  const RichParameterList& params, MeshDocument& md,
                                                                  unsigned int& postConditionMask,
                                                                  vcg::CallBackPos* cb) {
  const elastica::app::FilterId id = em::filterId(ID(action));
  postConditionMask = MeshModel::MM_NONE;  // until it succeeds
  em::RunOutcome outcome;
  try {
    outcome = em::runFilter(id, md, params, cb);
  } catch (...) {
    const std::string message = em::failureMessage(id);
    log(GLLogStream::WARNING, message);
    throw MLException(em::qs(message));
  }
  postConditionMask = static_cast<unsigned int>(em::keepUserShading(outcome.changed, md));  // view_shading.h
  for (const em::LogLine& line : outcome.log) log(line.warning ? GLLogStream::WARNING : GLLogStream::FILTER, line.text);
  return {};
}
