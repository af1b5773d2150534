#include <elastica/energy.h>
#include <elastica/parallel.h>

namespace elastica {

double totalCurvatureEnergy(const Topology& topo, const Geometry& geo, const Curvature& c,
                            const std::vector<std::uint8_t>* active) {
  const int nv = topo.vertexCount();
  double e = 0;
#pragma omp parallel for reduction(+ : e) schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i) {
    if (!geo.isRegular(i) || topo.isBoundaryVertex(i) || (active && !(*active)[i])) continue;
    e += (4 * c.H[i] * c.H[i] - 2 * c.K[i]) * geo.vertexArea[i];
  }
  return e;
}

}  // namespace elastica
