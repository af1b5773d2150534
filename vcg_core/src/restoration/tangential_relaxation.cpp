#include <elastica/geometry.h>
#include <elastica/topology.h>
#include "restoration/tangential_relaxation.h"

namespace elastica {

void relaxTangentially(TriMesh& mesh, const std::vector<std::uint8_t>& free, int iterations, double damping) {
  const Topology topo(mesh.vertexCount(), mesh.faces);
  Geometry geo;
  std::vector<Vec3> next;
  for (int it = 0; it < iterations; ++it) {
    computeGeometry(topo, mesh.positions, VertexArea::Mixed, geo);
    next = mesh.positions;
    for (int v = 0; v < mesh.vertexCount(); ++v) {
      if (!free[v] || topo.valence(v) == 0) continue;
      Vec3 c = Vec3::Zero();
      for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) c += mesh.positions[topo.ringVertex(k)];
      const Vec3 d = c / topo.valence(v) - mesh.positions[v];
      const Vec3& n = geo.vertexNormal[v];
      next[v] += damping * (d - d.dot(n) * n);
    }
    mesh.positions.swap(next);
  }
}

}  // namespace elastica
