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

// Fairing: Filters > "Smoothing, Fairing and Deformation"; the curvature filter there and under
// "Normals, Curvatures and Orientation"; hole filling under "Remeshing, Simplification and
// Reconstruction", beside MeshLab's Close Holes (which has class Remeshing).
MeshFilterInterface::FilterClass FilterElasticaPlugin::getClass(QAction* action) {
  switch (filterId(ID(action))) {
    case ea::FilterId::Curvature: return FilterClass(MeshFilterInterface::Smoothing | MeshFilterInterface::Normal);
    case ea::FilterId::FillHoles: return MeshFilterInterface::Remeshing;
    case ea::FilterId::Fairing: break;
  }
  return MeshFilterInterface::Smoothing;
}

int FilterElasticaPlugin::getRequirements(QAction*) { return MeshModel::MM_NONE; }

int FilterElasticaPlugin::getPreConditions(QAction*) const { return MeshModel::MM_FACENUMBER; }

// MeshLab 2020.09 asks for the post-condition twice: when the dialog opens (a mask without vertex
// or face numbers makes the filter previewable: rerun at every change of a parameter, with only
// the masked attributes saved for undoing it) and after applyFilter (the attributes whose render
// buffers it refreshes and whose display it turns on, even after a failed run). So the dialog gets
// the declared mask (fairing and filling may change the connectivity: not previewable) and the
// refresh gets what the run changed: a failed run, or a fill without holes, changes nothing, and
// quality and colour count only when the run wrote them. (MeshLab 2022.02 made this the
// applyFilter's postConditionMask out-parameter.)
int FilterElasticaPlugin::postCondition(QAction* action) const {
  const ea::FilterId id = filterId(ID(action));
  if (const std::optional<int>& ran = lastRunMask_[static_cast<size_t>(id)]) return *ran;
  if (id == ea::FilterId::Curvature) return MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
  return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE;
}

MeshFilterInterface::FILTER_ARITY FilterElasticaPlugin::filterArity(QAction*) const { return SINGLE_MESH; }

void FilterElasticaPlugin::initParameterSet(QAction* action, MeshModel& m, RichParameterList& params) {
  lastRunMask_[static_cast<size_t>(ID(action))].reset();  // a dialog opens: postCondition declares
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
  std::optional<int>& runMask = lastRunMask_[static_cast<size_t>(ID(action))];
  runMask = int(MeshModel::MM_NONE);  // until it succeeds
  try {
    MeshModel* mm = md.mm();
    if (mm == nullptr) throw elastica::InvalidInputError("no current mesh");
    const ea::FilterId id = filterId(ID(action));
    const ea::FilterSpec spec = ea::filterSpec(id, ea::meshFacts(mm->cm));
    name = spec.name;
    const ea::ParamValues values = readParameters(spec, params);
    ea::Progress progress;
    if (cb) progress = [cb](int percent, const std::string& what) { return cb(percent, what.c_str()); };

    const ea::AppliedFilter applied = ea::applyFilter(id, mm->cm, values, progress);
    const ea::MeshChanges& changed = applied.changed;
    int mask = MeshModel::MM_NONE;
    if (changed.positions) mask |= MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL;
    if (changed.connectivity) mask |= MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE;
    if (changed.selection) mask |= MeshModel::MM_FACEFLAGSELECT | MeshModel::MM_VERTFLAGSELECT;
    if (changed.curvature) {
      mask |= MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
      mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
    }
    if (changed.positions || changed.connectivity) mm->UpdateBoxAndNormals();
    runMask = mask;
    static const std::string kWarning = "warning: ";
    for (const std::string& line : applied.log) {
      if (line.compare(0, kWarning.size(), kWarning) == 0)
        Log(GLLogStream::WARNING, "%s: %s", name.c_str(), line.c_str());
      else
        Log("%s: %s", name.c_str(), line.c_str());
    }
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
