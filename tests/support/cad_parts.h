// SPDX-License-Identifier: GPL-3.0-or-later
// Generated CAD tessellations: parts whose flat and cylindrical sides are drawn with long thin
// triangles meeting at sharp edges, as CAD exporters write them (issue 40 item 3).
#pragma once

#include <elastica/types.h>

#include <cmath>
#include <utility>

namespace elastica::test {

/// A ring of rectangular section (a washer, or a thin-walled tube): radii `outer` and `inner`
/// about the x axis, from x = −halfWidth to halfWidth, `segments` around. Each of its four sides
/// is one strip of slivers (two triangles per segment), and its four rims are sharp (90°) edges.
inline TriMesh cadRing(int segments, double outer, double inner, double halfWidth) {
  TriMesh ring;
  for (const auto& [radius, x] : {std::pair{outer, -halfWidth}, {outer, halfWidth}, {inner, halfWidth}, {inner, -halfWidth}})
    for (int k = 0; k < segments; ++k) {
      const double a = 2 * M_PI * k / segments;
      ring.positions.emplace_back(x, radius * std::cos(a), radius * std::sin(a));
    }
  for (int k = 0; k < segments; ++k)
    for (int side = 0; side < 4; ++side) {
      const int next = (side + 1) % 4, k1 = (k + 1) % segments;
      ring.faces.push_back({side * segments + k, side * segments + k1, next * segments + k1});
      ring.faces.push_back({side * segments + k, next * segments + k1, next * segments + k});
    }
  return ring;
}

}  // namespace elastica::test
