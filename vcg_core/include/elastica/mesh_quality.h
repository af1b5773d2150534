// Triangle quality measures reported by the restoration and checked by its tests.
#pragma once

#include <elastica/types.h>

namespace elastica {

/// Smallest corner angle, in degrees, over the faces [firstFace, end) of `mesh` (180 if none).
double smallestAngleDegrees(const TriMesh& mesh, int firstFace = 0);

}  // namespace elastica
