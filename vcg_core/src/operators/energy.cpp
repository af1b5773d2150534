// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/energy.h>
#include "support/parallel.h"

namespace elastica {

double totalCurvatureEnergy(const Topology& topo, const Geometry& geo, const Curvature& c,
                            const std::vector<std::uint8_t>* active) {
  const int nv = topo.vertexCount();
  return parallelSum(nv, [&](int i) {
    return active && !(*active)[i] ? 0.0 : vertexCurvatureEnergy(topo, geo, c, i);
  });
}

}  // namespace elastica
