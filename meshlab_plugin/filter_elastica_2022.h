// SPDX-License-Identifier: GPL-3.0-or-later
// The plugin class for MeshLab 2022.02 (Debian 13; ELASTICA_MESHLAB_API=2022): FilterPlugin, a thin
// adapter over the shared filter code (filter_common.h), which does the work. Compile-checked
// against Debian 13's meshlab source package (ctest plugin_meshlab2022_compile), not run-tested:
// Debian 12 cannot install MeshLab 2022.02.
#pragma once

#include "meshlab_api.h"

#include <QObject>

#include <map>
#include <string>

class FilterElasticaPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  FilterElasticaPlugin();
  ~FilterElasticaPlugin() override;

  QString pluginName() const override;
  QString filterName(ActionIDType filter) const override;
  QString filterInfo(ActionIDType filter) const override;
  FilterClass getClass(const QAction* action) const override;
  int getRequirements(const QAction* action) override;
  int getPreConditions(const QAction* action) const override;
  /// What the filter may change, declared (MeshLab's preview): what a run changed goes into
  /// applyFilter's postConditionMask.
  int postCondition(const QAction* action) const override;
  FilterArity filterArity(const QAction* action) const override;
  RichParameterList initParameterList(const QAction* action, const MeshModel& m) override;
  /// Sets postConditionMask to what the run changed (MM_NONE: nothing). A failure is logged and
  /// thrown as MLException with the mesh unchanged.
  std::map<std::string, QVariant> applyFilter(const QAction* action, const RichParameterList& params,
                                              MeshDocument& md, unsigned int& postConditionMask,
                                              vcg::CallBackPos* cb) override;
};
