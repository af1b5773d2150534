// The MeshLab filter plugin (libfilter_elastica.so): a thin adapter between MeshLab's filter
// interface and the shared filter layer (filters/: names, parameters, core calls). It owns no
// numerics: parameters go from RichParameters into ParamValues, the mesh from CMeshO into the core
// and back, progress into MeshLab's callback, exceptions into MeshLab's error message and log.
#pragma once

#include <common/interfaces.h>

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
