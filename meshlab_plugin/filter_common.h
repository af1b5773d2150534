// SPDX-License-Identifier: GPL-3.0-or-later
// The filters' MeshLab side, shared by the plugin classes of both APIs (meshlab_api.h): MeshLab's
// RichParameters <-> the application layer's parameters (app/filter_spec.h), the current mesh
// through the application layer (app/filter_apply.h) and back, what a run changed as a MeshLab
// mask, and errors as one message. It owns no numerics and never talks to MeshLab's log itself:
// the plugin classes log the lines it returns, in their API's way.
#pragma once

#include "meshlab_api.h"

#include <elastica/app/filter_spec.h>

#include <QString>

#include <string>
#include <vector>

namespace elastica::meshlab {

QString qs(const std::string& s);

/// The filter of a plugin action id (the ids are app::FilterId values).
app::FilterId filterId(int actionId);
/// Every filter, in menu order.
std::vector<app::FilterId> filterIds();
QString filterName(app::FilterId id);
QString filterInfo(app::FilterId id);

/// The menus: fairing and curvature under "Smoothing, Fairing and Deformation" (curvature also
/// under "Normals, Curvatures and Orientation"), hole filling under "Remeshing, Simplification and
/// Reconstruction", beside MeshLab's Close Holes.
FilterBase::FilterClass filterClass(app::FilterId id);

/// What a filter may change, declared before it runs (when its dialog opens). MeshLab makes a
/// filter previewable when this mask has no vertex or face numbers: curvature only.
int declaredChanges(app::FilterId id);

/// The filter's parameters for the dialog, with defaults for mesh `m` (its selection).
void addParameters(app::FilterId id, const CMeshO& m, RichParameterList& params);

struct LogLine {
  bool warning = false;
  std::string text;  ///< starts with the filter's name
};

/// A run that succeeded: what it changed, as a MeshLab mask (MM_NONE: nothing, e.g. a fill
/// without holes), and its lines for MeshLab's log.
struct RunOutcome {
  int changed = MeshModel::MM_NONE;
  std::vector<LogLine> log;
};

/// Runs filter `id` on the current mesh of `md` with the dialog's (or a script's) parameters,
/// progress into `cb` (may be null; it returning false cancels).
/// @throws std::exception (elastica::Error, std::bad_alloc, ...) with the mesh unchanged.
RunOutcome runFilter(app::FilterId id, MeshDocument& md, const RichParameterList& params, vcg::CallBackPos* cb);

/// The message for the exception being handled (call it in a catch block): the filter's name,
/// then what went wrong; the mesh is unchanged.
std::string failureMessage(app::FilterId id);

}  // namespace elastica::meshlab
