// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/amount_operators.h"

#include <elastica/geometry.h>

#include <cmath>

namespace elastica {

void graphAmountOperators(const Topology& topo, const std::vector<Vec3>& positions, std::vector<double>& edgeWeight,
                          std::vector<double>& vertexArea) {
  const double halfCot60 = 0.5 / std::sqrt(3.0);  // ½ cot 60°: one face's share of its edges' weight
  edgeWeight.assign(static_cast<std::size_t>(topo.edgeCount()), 0.0);
  for (int e = 0; e < topo.edgeCount(); ++e) edgeWeight[e] = topo.isBoundaryEdge(e) ? halfCot60 : 2 * halfCot60;
  const double ell = meanEdgeLength(topo, positions);
  const double third = std::sqrt(3.0) / 4 * ell * ell / 3;  // a third of an equilateral face's area
  vertexArea.assign(static_cast<std::size_t>(topo.vertexCount()), 0.0);
  for (int v = 0; v < topo.vertexCount(); ++v) vertexArea[v] = third * (topo.cornerEnd(v) - topo.cornerBegin(v));
}

}  // namespace elastica
