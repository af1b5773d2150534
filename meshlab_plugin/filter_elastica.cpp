#include "filter_elastica.h"

#include <elastica/errors.h>
#include <elastica/app/filter_apply.h>
#include <elastica/app/filter_spec.h>

#include <new>

namespace ea = elastica::app;

namespace {

ea::FilterId filterId(MeshFilterInterface::FilterIDType id) { return static_cast<ea::FilterId>(id); }

QString qs(const std::string& s) { return QString::fromStdString(s); }

// The filter's parameters, read back from MeshLab's list by the shared spec's names and types.
ea::ParamValues readParameters(const ea::FilterSpec& spec, const RichParameterList& params) {
  ea::ParamValues v;
  for (const ea::ParamSpec& p : spec.params) {
    const QString name = qs(p.name);
    if (!params.hasParameter(name)) throw elastica::InvalidInputError("parameter '" + p.name + "' is missing");
    switch (p.type) {
      case ea::ParamType::Bool: v.set(p.name, params.getBool(name) ? 1 : 0); break;
      case ea::ParamType::Int: v.set(p.name, params.getInt(name)); break;
      case ea::ParamType::Float: v.set(p.name, params.getFloat(name)); break;
      case ea::ParamType::Enum: v.set(p.name, params.getEnum(name)); break;
    }
  }
  return v;
}

}  // namespace

FilterElasticaPlugin::FilterElasticaPlugin() {
  for (const ea::FilterSpec& s : ea::allFilters({})) {
    typeList << static_cast<FilterIDType>(s.id);
    actionList << new QAction(qs(s.name), this);
  }
}

FilterElasticaPlugin::~FilterElasticaPlugin() = default;  // the actions are children of this QObject

QString FilterElasticaPlugin::pluginName() const { return "FilterElastica"; }

QString FilterElasticaPlugin::filterName(FilterIDType filter) const {
  return qs(ea::filterSpec(filterId(filter), {}).name);
}

QString FilterElasticaPlugin::filterInfo(FilterIDType filter) const {
  return qs(ea::filterSpec(filterId(filter), {}).info);
}

// Filters > "Smoothing, Fairing and Deformation"; the curvature filter also under Normal/Curvature.
MeshFilterInterface::FilterClass FilterElasticaPlugin::getClass(QAction* action) {
  if (filterId(ID(action)) == ea::FilterId::Curvature)
    return FilterClass(MeshFilterInterface::Smoothing | MeshFilterInterface::Normal);
  return MeshFilterInterface::Smoothing;
}

int FilterElasticaPlugin::getRequirements(QAction*) { return MeshModel::MM_NONE; }

int FilterElasticaPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

int FilterElasticaPlugin::postCondition(QAction* action) const {
  if (filterId(ID(action)) == ea::FilterId::Curvature)
    return MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
  return MeshModel::MM_ALL;  // fairing may subdivide: connectivity changes
}

MeshFilterInterface::FILTER_ARITY FilterElasticaPlugin::filterArity(QAction*) const { return SINGLE_MESH; }

void FilterElasticaPlugin::initParameterSet(QAction* action, MeshModel& m, RichParameterList& params) {
  const ea::FilterSpec spec = ea::filterSpec(filterId(ID(action)), ea::meshFacts(m.cm));
  for (const ea::ParamSpec& p : spec.params) {
    const QString name = qs(p.name), label = qs(p.label), tip = qs(p.tooltip);
    switch (p.type) {
      case ea::ParamType::Bool: params.addParam(RichBool(name, p.defaultValue != 0, label, tip)); break;
      case ea::ParamType::Int: params.addParam(RichInt(name, int(p.defaultValue), label, tip)); break;
      case ea::ParamType::Float: params.addParam(RichFloat(name, float(p.defaultValue), label, tip)); break;
      case ea::ParamType::Enum: {
        QStringList values;
        for (const std::string& e : p.enumValues) values << qs(e);
        params.addParam(RichEnum(name, int(p.defaultValue), values, label, tip));
        break;
      }
    }
  }
}

bool FilterElasticaPlugin::applyFilter(QAction* action, MeshDocument& md, const RichParameterList& params,
                                       vcg::CallBackPos* cb) {
  std::string name = "Discrete Elastica";
  try {
    MeshModel* mm = md.mm();
    if (mm == nullptr) throw elastica::InvalidInputError("no current mesh");
    const ea::FilterId id = filterId(ID(action));
    const ea::FilterSpec spec = ea::filterSpec(id, ea::meshFacts(mm->cm));
    name = spec.name;
    const ea::ParamValues values = readParameters(spec, params);
    ea::Progress progress;
    if (cb) progress = [cb](int percent, const std::string& what) { return cb(percent, what.c_str()); };

    const std::vector<std::string> summary = ea::applyFilter(id, mm->cm, values, progress);
    if (ea::filterOutputs(id, values).curvature) mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
    mm->UpdateBoxAndNormals();
    for (const std::string& line : summary) Log("%s: %s", name.c_str(), line.c_str());
    return true;
  } catch (const std::bad_alloc&) {
    errorMessage = qs(name + ": out of memory; the mesh is unchanged");
  } catch (const std::exception& e) {
    errorMessage = qs(name + ": " + e.what());
  } catch (...) {
    errorMessage = qs(name + ": unexpected error; the mesh is unchanged");
  }
  Log(GLLogStream::WARNING, qUtf8Printable(errorMessage));
  return false;
}
