// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/constraints.h"

namespace elastica {

VertexRoles assignRoles(const Topology& topo, const std::vector<std::uint8_t>* faceSelected, BoundaryMode mode) {
  const int nv = topo.vertexCount(), nf = topo.faceCount();
  const bool all = !faceSelected || faceSelected->empty();
  std::vector<std::uint8_t> movable(nv, 0);
  for (int v = 0; v < nv; ++v) {
    if (topo.isIsolatedVertex(v)) continue;
    bool strict = true;
    for (int k = topo.cornerBegin(v); k < topo.cornerEnd(v) && strict && !all; ++k)
      strict = (*faceSelected)[topo.corner(k) / 3] != 0;
    movable[v] = strict;
  }

  VertexRoles r;
  r.free.assign(nv, 0);
  r.sliding.assign(nv, 0);
  for (int v = 0; v < nv; ++v) {
    if (!movable[v]) continue;
    if (topo.isBoundaryVertex(v)) {
      if (mode == BoundaryMode::Slide) r.sliding[v] = 1;
      continue;
    }
    bool nearBoundary = false;
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v) && !nearBoundary; ++k)
      nearBoundary = topo.isBoundaryVertex(topo.ringVertex(k));
    r.free[v] = mode == BoundaryMode::Slide || !nearBoundary;
  }

  r.active.assign(nv, 0);
  for (int v = 0; v < nv; ++v) {
    if (!r.free[v]) continue;
    ++r.freeCount;
    r.active[v] = 1;
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) r.active[topo.ringVertex(k)] = 1;
  }
  for (int v = 0; v < nv; ++v) r.slidingCount += r.sliding[v];
  r.activeFace.assign(nf, 0);
  for (int f = 0; f < nf; ++f) {
    for (int v : topo.faces()[f]) r.activeFace[f] |= r.free[v] | r.sliding[v];
  }
  return r;
}

}  // namespace elastica
