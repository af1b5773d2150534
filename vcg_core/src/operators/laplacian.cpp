// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/laplacian.h>
#include "support/parallel.h"

namespace elastica {
namespace {

// One gather loop for both value types: each vertex reads its own ring, so the loop has no
// write conflicts and parallelises over vertices.
template <class T, class Zero>
void gatherLaplacian(const Topology& topo, const std::vector<double>& edgeWeight, const std::vector<double>& vertexArea,
                     const std::vector<T>& f, std::vector<T>& out, Zero zero) {
  const int nv = topo.vertexCount();
  out.resize(nv);
  parallelFor(nv, [&](int i) {
    T sum = zero();
    if (vertexArea[i] > 0) {
      for (int k = topo.ringBegin(i); k < topo.ringEnd(i); ++k)
        sum += edgeWeight[topo.ringEdge(k)] * (f[topo.ringVertex(k)] - f[i]);
      sum /= vertexArea[i];
    }
    out[i] = sum;
  });
}

}  // namespace

void cotanLaplacian(const Topology& topo, const Geometry& g, const std::vector<Vec3>& p, std::vector<Vec3>& out) {
  cotanLaplacian(topo, g.edgeWeight, g.vertexArea, p, out);
}

void cotanLaplacian(const Topology& topo, const std::vector<double>& edgeWeight, const std::vector<double>& vertexArea,
                    const std::vector<Vec3>& p, std::vector<Vec3>& out) {
  gatherLaplacian(topo, edgeWeight, vertexArea, p, out, [] { return Vec3(Vec3::Zero()); });
}

void cotanLaplacian(const Topology& topo, const Geometry& g, const std::vector<double>& f,
                    std::vector<double>& out) {
  gatherLaplacian(topo, g.edgeWeight, g.vertexArea, f, out, [] { return 0.0; });
}

}  // namespace elastica
