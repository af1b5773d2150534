// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle quality measures reported by the restoration and checked by its tests.
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Smallest corner angle, in degrees, of the triangle (a, b, c).
double smallestAngleDegrees(const Vec3& a, const Vec3& b, const Vec3& c);

/// Smallest corner angle, in degrees, over the faces [firstFace, end) of `mesh` (180 if none).
double smallestAngleDegrees(const TriMesh& mesh, int firstFace = 0);

/// Smallest corner angle, in degrees, over the faces flagged in `faceFlags` (180 if none).
double smallestAngleDegrees(const TriMesh& mesh, const std::vector<std::uint8_t>& faceFlags);

}  // namespace elastica
