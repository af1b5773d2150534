// SPDX-License-Identifier: GPL-3.0-or-later
// The thickness of a closed part: how thin its thinnest feature is (a wall, a web, the tube of a
// handle), for sizing a CAD tessellation's working resolution (issue 40 item 3,
// flow/mesh_quality_stage.h: cadWorkingEdgeLength).
#pragma once

#include <elastica/types.h>

#include <vector>

namespace elastica {

/// Local thickness of a closed triangle mesh, one value per face: the distance from the face's
/// centroid along its inward normal (inward by the sign of the enclosed volume, so either
/// orientation) to the first other face the ray meets. Infinity where the ray meets none (an open
/// mesh, a degenerate face). A slab of thickness t gives t on its two large sides; a torus of tube
/// radius r gives about 2r everywhere; a sphere of radius R its diameter 2R.
std::vector<double> faceThickness(const TriMesh& mesh);

/// The area-weighted `quantile` (in [0, 1]) of faceThickness over the faces where it is finite:
/// the thickness below which that fraction of the surface lies. A low quantile, so one sliver or
/// one small chamfer does not decide. 0 if no face has a finite thickness.
double thinnestFeature(const TriMesh& mesh, double quantile);

}  // namespace elastica
