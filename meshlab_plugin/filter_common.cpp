// SPDX-License-Identifier: GPL-3.0-or-later
#include "filter_common.h"

#include <elastica/errors.h>
#include <elastica/app/filter_apply.h>

#include <exception>
#include <new>

namespace elastica::meshlab {
namespace ea = elastica::app;

namespace {

// The filter's parameters, read back from MeshLab's list by the shared spec's names and types.
ea::ParamValues readParameters(const ea::FilterSpec& spec, const RichParameterList& params) {
  ea::ParamValues v;
  for (const ea::ParamSpec& p : spec.params) {
    if (!p.inMeshLab()) continue;
    const QString name = qs(p.name);
    if (!params.hasParameter(name)) throw InvalidInputError("parameter '" + p.name + "' is missing");
    switch (p.type) {
      case ea::ParamType::Bool: v.set(p.name, params.getBool(name) ? 1 : 0); break;
      case ea::ParamType::Int: v.set(p.name, params.getInt(name)); break;
      case ea::ParamType::Float: v.set(p.name, params.getFloat(name)); break;
      case ea::ParamType::Enum: v.set(p.name, params.getEnum(name)); break;
      case ea::ParamType::AbsPerc: v.set(p.name, params.getAbsPerc(name)); break;
    }
  }
  return v;
}

// What a run changed, as the mask MeshLab refreshes (and shows) after it.
int changedMask(const ea::MeshChanges& changed) {
  int mask = MeshModel::MM_NONE;
  if (changed.positions) mask |= MeshModel::MM_VERTCOORD | MeshModel::MM_VERTNORMAL | MeshModel::MM_FACENORMAL;
  if (changed.connectivity) mask |= MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE;
  if (changed.selection) mask |= MeshModel::MM_FACEFLAGSELECT | MeshModel::MM_VERTFLAGSELECT;
  if (changed.curvature) mask |= MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
  return mask;
}

}  // namespace

QString qs(const std::string& s) { return QString::fromStdString(s); }

ea::FilterId filterId(int actionId) { return static_cast<ea::FilterId>(actionId); }

std::vector<ea::FilterId> filterIds() {
  std::vector<ea::FilterId> ids;
  for (const ea::FilterSpec& s : ea::allFilters({})) ids.push_back(s.id);
  return ids;
}

QString filterName(ea::FilterId id) { return qs(ea::filterSpec(id, {}).name); }

QString filterInfo(ea::FilterId id) { return qs(ea::filterSpec(id, {}).info); }

FilterBase::FilterClass filterClass(ea::FilterId id) {
  switch (id) {
    case ea::FilterId::Curvature: return FilterBase::FilterClass(FilterBase::Smoothing | FilterBase::Normal);
    case ea::FilterId::FillHoles: return FilterBase::Remeshing;
    case ea::FilterId::Fairing: break;
  }
  return FilterBase::Smoothing;
}

int declaredChanges(ea::FilterId id) {
  if (id == ea::FilterId::Curvature) return MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;
  return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE;  // fairing and filling may change the connectivity
}

void addParameters(ea::FilterId id, const CMeshO& m, RichParameterList& params) {
  const ea::MeshFacts facts = ea::meshFacts(m);
  const ea::FilterSpec spec = ea::filterSpec(id, facts);
  for (const ea::ParamSpec& p : spec.params) {
    if (!p.inMeshLab()) continue;
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
      case ea::ParamType::AbsPerc:  // the length; the dialog shows it as a % of the diagonal too
        params.addParam(RichLength(name, float(p.defaultValue), 0.f, float(facts.diagonal), label, tip));
        break;
    }
  }
}

RunOutcome runFilter(ea::FilterId id, MeshDocument& md, const RichParameterList& params, vcg::CallBackPos* cb) {
  MeshModel* mm = md.mm();
  if (mm == nullptr) throw InvalidInputError("no current mesh");
  const ea::FilterSpec spec = ea::filterSpec(id, ea::meshFacts(mm->cm));
  const ea::ParamValues values = readParameters(spec, params);
  ea::Progress progress;
  if (cb) progress = [cb](int percent, const std::string& what) { return cb(percent, what.c_str()); };

  const ea::AppliedFilter applied = ea::applyFilter(id, mm->cm, values, progress);
  RunOutcome outcome;
  outcome.changed = changedMask(applied.changed);
  if (applied.changed.curvature) mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  if (applied.changed.positions || applied.changed.connectivity) updateBoxAndNormals(*mm);
  for (const ea::LogLine& line : applied.log) {
    const bool warning = line.severity == ea::Severity::Warning;
    outcome.log.push_back({warning, spec.name + ": " + (warning ? "warning: " : "") + line.text});
  }
  return outcome;
}

std::string failureMessage(ea::FilterId id) {
  const std::exception_ptr failure = std::current_exception();
  std::string name = "Discrete Elastica";
  try {
    name = ea::filterSpec(id, {}).name;
  } catch (...) {  // not one of our ids: keep the generic name
  }
  try {
    std::rethrow_exception(failure);
  } catch (const std::bad_alloc&) {
    return name + ": out of memory; the mesh is unchanged";
  } catch (const std::exception& e) {
    return name + ": " + e.what();
  } catch (...) {
    return name + ": unexpected error; the mesh is unchanged";
  }
}

}  // namespace elastica::meshlab
