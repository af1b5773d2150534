// SPDX-License-Identifier: GPL-3.0-or-later
// The user's shading after a filter. After applyFilter, every MeshLab (2020.09, 2022.02, 2025.07)
// turns on, in each view of the mesh, the normals the run reports as changed
// (MLPoliciesStandAloneFunctions::updatedRendAttsAccordingToPriorities): a fairing reported with
// vertex normals came back shaded "Vert" in a view that was shaded "Face". So a run with the
// connectivity kept reports vertex normals only where some view shows them.
#pragma once

#include "meshlab_api.h"

namespace elastica::meshlab {

/// `changed` (MeshModel::MM_* bits a run changed) with MM_VERTNORMAL cleared when the run kept
/// the connectivity (no MM_FACEVERT: MeshLab rebuilds every buffer, and shades by vertex, when it
/// changed) and every view of the document's current mesh draws it without vertex normals. Without
/// any view (meshlabserver, the in-process tests) the mask is returned unchanged.
int keepUserShading(int changed, MeshDocument& md);

}  // namespace elastica::meshlab
