#include <elastica/semi_implicit_system.h>

#include <utility>

namespace elastica {

void assembleSemiImplicitSystem(const Topology& topo, const Geometry& geo, const std::vector<std::uint8_t>& active,
                                const std::vector<int>& freeIndex, int n, const std::vector<double>& speed, double tau,
                                std::vector<Eigen::Triplet<double>>& trip, Eigen::SparseMatrix<double>& K,
                                Eigen::VectorXd& rhs) {
  const int nv = topo.vertexCount();
  trip.clear();
  std::vector<std::pair<int, double>> column;  // (row, C_ij) of the free vertices around active vertex i
  for (int i = 0; i < nv; ++i) {
    if (!active[i] || !geo.isRegular(i)) continue;
    column.clear();
    double diagonal = 0;
    for (int k = topo.ringBegin(i); k < topo.ringEnd(i); ++k) {
      const double w = geo.edgeWeight[topo.ringEdge(k)];
      diagonal -= w;
      const int r = freeIndex[topo.ringVertex(k)];
      if (r >= 0) column.emplace_back(r, w);
    }
    if (freeIndex[i] >= 0) column.emplace_back(freeIndex[i], diagonal);
    const double s = 0.5 * tau / geo.vertexArea[i];
    for (const auto& [r1, c1] : column)
      for (const auto& [r2, c2] : column) trip.emplace_back(r1, r2, s * c1 * c2);
  }
  rhs.resize(n);
  for (int v = 0; v < nv; ++v) {
    const int r = freeIndex[v];
    if (r < 0) continue;
    trip.emplace_back(r, r, geo.vertexArea[v]);
    rhs[r] = tau * geo.vertexArea[v] * speed[v];
  }
  K.resize(n, n);
  K.setFromTriplets(trip.begin(), trip.end());
}

}  // namespace elastica
