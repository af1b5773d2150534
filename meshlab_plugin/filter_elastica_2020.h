// SPDX-License-Identifier: GPL-3.0-or-later
// The plugin class for MeshLab 2020.09 (Debian 12; ELASTICA_MESHLAB_API=2020): MeshFilterInterface,
// a thin adapter over the shared filter code (filter_common.h), which does the work. Built as
// libfilter_elastica.so, run-tested in meshlabserver and the GUI (tests/plugin/).
#pragma once

#include "meshlab_api.h"

#include <QObject>

#include <array>
#include <optional>

class FilterElasticaPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  FilterElasticaPlugin();
  ~FilterElasticaPlugin() override;

  QString pluginName() const override;
  QString filterName(FilterIDType filter) const override;
  QString filterInfo(FilterIDType filter) const override;
  FilterClass getClass(QAction* action) override;
  int getRequirements(QAction* action) override;
  int getPreConditions(QAction* action) const override;
  int postCondition(QAction* action) const override;
  FILTER_ARITY filterArity(QAction* action) const override;
  using MeshFilterInterface::initParameterSet;  // keep the MeshDocument overload visible
  void initParameterSet(QAction* action, MeshModel& m, RichParameterList& params) override;
  /// Never throws: a failure sets errorMessage, logs it (meshlabserver prints only the log) and
  /// returns false with the mesh unchanged.
  bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& params, vcg::CallBackPos* cb) override;

 private:
  /// What the last run of each filter changed, as a MeshLab mask (MM_NONE after a failure), for
  /// postCondition; unset until it runs and again when its dialog opens (initParameterSet), so
  /// that the dialog sees the declared mask.
  std::array<std::optional<int>, 3> lastRunMask_;
};
