// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's hole filling (Polygon Mesh Processing: triangulate_refine_and_fair_hole), for comparison
// only: built when Debian's libcgal-dev is present, never a runtime dependency of Elastica.
#pragma once

#include <elastica/types.h>

namespace elastica::bench {

/// Fills every hole of `mesh` with CGAL's triangulate_refine_and_fair_hole (default parameters:
/// Liepa triangulation, √2 density refinement, one bi-Laplace solve with cotangent weights).
/// New vertices and faces are appended. Returns the number of holes filled successfully.
int cgalFillHoles(TriMesh& mesh);

}  // namespace elastica::bench
