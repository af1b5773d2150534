// The holes of a mesh: its boundary loops, walked in the direction a filling patch must take so
// that the new faces are oriented like the old ones.
#pragma once

#include <elastica/topology.h>

#include <vector>

namespace elastica {

/// One boundary loop. `vertices[i] → vertices[i+1]` (cyclically) is the direction of the *hole*:
/// the mesh face on that edge traverses it the other way. `outside[i]` is the third vertex of that
/// mesh face (its tangent plane is what a patch continues).
struct HoleLoop {
  std::vector<int> vertices;
  std::vector<int> outside;
  /// The loop passes through a vertex more than once (two holes touching at a vertex, or a hole
  /// pinched by a non-manifold vertex): not fillable as one disc.
  bool pinched = false;
  int edgeCount() const { return static_cast<int>(vertices.size()); }
};

/// All boundary loops of a mesh, each starting at its smallest boundary half-edge (deterministic).
std::vector<HoleLoop> findHoleLoops(const Topology& topo);

/// The smallest angle any patch of `loop` can have, in degrees, as far as its border decides: the
/// smallest angle between two consecutive border edges at a corner that the hole's side sees as
/// convex (the mesh's own faces there span more than 180°). A patch face holding that corner has
/// at most that angle; a fan of several faces there only splits it. 180 when no corner is convex.
double borderCornerBoundDegrees(const std::vector<Vec3>& positions, const Topology& topo, const HoleLoop& loop);

}  // namespace elastica
