// SPDX-License-Identifier: GPL-3.0-or-later
// Boundary vertices that slide along the mesh's original boundary polylines (BoundaryMode::Slide):
// they move only along the boundary, towards even spacing, and are projected back onto the
// polylines recorded at the start, so the boundary curve itself never changes.
#pragma once

#include <elastica/topology.h>
#include <elastica/types.h>

#include <array>
#include <cstdint>
#include <vector>

namespace elastica {

class BoundarySlider {
 public:
  /// Records the boundary polylines of the mesh as they are now.
  BoundarySlider(const Topology& topo, const std::vector<Vec3>& p);

  /// Attaches each sliding vertex to its nearest recorded segment (after any connectivity change).
  /// Corners (a turn of the boundary sharper than 30°) stay pinned.
  void attach(const Topology& topo, const std::vector<Vec3>& p, const std::vector<std::uint8_t>& sliding);

  /// Moves each sliding vertex the fraction `rate` of the way to the midpoint of its two boundary
  /// neighbours, along the boundary, then projects it onto the recorded polylines.
  void slide(const Topology& topo, std::vector<Vec3>& p, const std::vector<std::uint8_t>& sliding, double rate);

 private:
  Vec3 project(int vertex, const Vec3& q);

  std::vector<std::array<Vec3, 2>> segment_;        // recorded boundary segments
  std::vector<std::array<int, 2>> neighbourSegment_;  // the segments sharing each endpoint (-1: none)
  std::vector<int> vertexSegment_;                    // per vertex: the segment it lies on, or -1
  std::vector<Vec3> moved_;                           // scratch
};

}  // namespace elastica
