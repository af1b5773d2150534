// SPDX-License-Identifier: GPL-3.0-or-later
// The angle at a triangle's corner from its positions, written once. atan2 of |u × w| and u · w:
// accurate near 0 and π, where acos of the normalised dot product loses digits. (The per-step
// operators take corner angles from their cached areas and dot products, Geometry::cornerAngle;
// the border-angle passes compare cosines, which need no inverse trigonometry.)
#pragma once

#include <elastica/types.h>

#include <cmath>

namespace elastica {

/// The angle between vectors u and w, in radians, in [0, π]; 0 if either is zero.
inline double angleBetween(const Vec3& u, const Vec3& w) { return std::atan2(u.cross(w).norm(), u.dot(w)); }

/// The angle, in radians, at `apex` of the triangle (apex, a, b).
inline double cornerAngle(const Vec3& apex, const Vec3& a, const Vec3& b) { return angleBetween(a - apex, b - apex); }

}  // namespace elastica
