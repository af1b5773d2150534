#include <elastica/energy.h>
#include "support/parallel.h"

namespace elastica {

double totalCurvatureEnergy(const Topology& topo, const Geometry& geo, const Curvature& c,
                            const std::vector<std::uint8_t>* active) {
  const int nv = topo.vertexCount();
  return parallelSum(nv, [&](int i) {
    if (!geo.isRegular(i) || topo.isBoundaryVertex(i) || (active && !(*active)[i])) return 0.0;
    return (4 * c.H[i] * c.H[i] - 2 * c.K[i]) * geo.vertexArea[i];
  });
}

}  // namespace elastica
