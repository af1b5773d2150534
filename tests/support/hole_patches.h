// SPDX-License-Identifier: GPL-3.0-or-later
// A hole closed by the restoration's first step (Liepa's triangulation, no new vertices): the start
// that the refinement, bi-Laplace and remeshing tests work on. Uses the core's private headers:
// include it only from tests that link elastica::core_internal.
#pragma once

#include <elastica/topology.h>
#include <elastica/types.h>
#include "restoration/hole_boundary.h"
#include "restoration/hole_triangulation.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace elastica::test {

/// True if `a` and `b` are joined by an edge of `topo` (triangulateHole's edgeExists).
inline bool joined(const Topology& topo, int a, int b) {
  for (int k = topo.ringBegin(a); k < topo.ringEnd(a); ++k)
    if (topo.ringVertex(k) == b) return true;
  return false;
}

/// The boundary loop of `m` with the fewest edges (a cut mesh's hole rather than its rim).
inline HoleLoop smallestHole(const Topology& topo) {
  HoleLoop best;
  for (HoleLoop& loop : findHoleLoops(topo))
    if (best.vertices.empty() || loop.edgeCount() < best.edgeCount()) best = std::move(loop);
  return best;
}

/// A mesh whose hole has been triangulated: the patch's faces are appended and flagged.
struct PatchedHole {
  TriMesh mesh;
  std::vector<std::uint8_t> patchFace;  ///< one byte per face: 1 on the patch
  int firstNew = 0;                     ///< vertices from here on are the patch's own (none yet)
  int firstPatchFace = 0;               ///< faces from here on are the patch's
};

/// `cut`'s smallest hole closed by triangulateHole (std::nullopt if it cannot be).
inline std::optional<PatchedHole> triangulateSmallestHole(const TriMesh& cut) {
  const Topology topo(cut.vertexCount(), cut.faces);
  const auto tris = triangulateHole(cut.positions, smallestHole(topo), [&](int a, int b) { return joined(topo, a, b); });
  if (!tris) return std::nullopt;
  PatchedHole p{cut, std::vector<std::uint8_t>(cut.faces.size(), 0), cut.vertexCount(), cut.faceCount()};
  p.mesh.faces.insert(p.mesh.faces.end(), tris->begin(), tris->end());
  p.patchFace.resize(p.mesh.faces.size(), 1);
  return p;
}

}  // namespace elastica::test
