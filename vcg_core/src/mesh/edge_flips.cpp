#include <elastica/topology.h>
#include "mesh/edge_flips.h"

#include <algorithm>
#include <set>
#include <utility>

namespace elastica {
namespace {

// Flips beyond this much (radians) past π only: avoids flipping back and forth on cocircular quads.
constexpr double kAngleSlack = 1e-6;

double angleAt(const Vec3& apex, const Vec3& a, const Vec3& b) {
  const Vec3 u = a - apex, w = b - apex;
  return std::atan2(u.cross(w).norm(), u.dot(w));
}

}  // namespace

int flipToDelaunay(TriMesh& mesh, const std::vector<std::uint8_t>& movable, int maxPasses) {
  return flipToDelaunay(
      mesh, [&](int a, int b, int c, int d, int, int) { return movable[a] && movable[b] && movable[c] && movable[d]; },
      maxPasses);
}

int flipToDelaunay(TriMesh& mesh, const FlipFilter& allowed, int maxPasses) {
  const auto& p = mesh.positions;
  int total = 0;
  for (int pass = 0; pass < maxPasses; ++pass) {
    const Topology topo(mesh.vertexCount(), mesh.faces);
    std::vector<std::uint8_t> touched(mesh.faces.size(), 0);
    // Edges this pass created: `topo` predates them, and two quads can share their far corners
    // (on a thin tube, c and d are both neighbours of a, b and of a', b'): the second flip would
    // make c–d an edge of four faces.
    std::set<std::pair<int, int>> created;
    int flips = 0;
    for (int e = 0; e < topo.edgeCount(); ++e) {
      const auto& oc = topo.edgeOppositeCorners(e);
      if (oc[1] < 0) continue;
      const int f0 = oc[0] / 3, f1 = oc[1] / 3;
      if (touched[f0] || touched[f1]) continue;
      // f0 = (a, b, c) with c opposite the edge; f1 holds the edge as (b, a) with d opposite.
      const int c = mesh.faces[f0][oc[0] % 3], d = mesh.faces[f1][oc[1] % 3];
      const int a = mesh.faces[f0][(oc[0] % 3 + 1) % 3], b = mesh.faces[f0][(oc[0] % 3 + 2) % 3];
      if (c == d || !allowed(a, b, c, d, f0, f1)) continue;
      if (angleAt(p[c], p[a], p[b]) + angleAt(p[d], p[a], p[b]) <= M_PI + kAngleSlack) continue;
      bool exists = false;
      for (int k = topo.ringBegin(c); k < topo.ringEnd(c) && !exists; ++k) exists = topo.ringVertex(k) == d;
      if (exists || created.count(std::minmax(c, d))) continue;
      // New faces (a, d, c) and (d, b, c): same orientation as the old pair, or no flip.
      const Vec3 before = (p[b] - p[a]).cross(p[c] - p[a]) + (p[a] - p[b]).cross(p[d] - p[b]);
      const Vec3 n1 = (p[d] - p[a]).cross(p[c] - p[a]), n2 = (p[b] - p[d]).cross(p[c] - p[d]);
      if (n1.dot(before) <= 0 || n2.dot(before) <= 0) continue;
      mesh.faces[f0] = {a, d, c};
      mesh.faces[f1] = {d, b, c};
      touched[f0] = touched[f1] = 1;
      created.insert(std::minmax(c, d));
      ++flips;
    }
    total += flips;
    if (flips == 0) break;
  }
  return total;
}

}  // namespace elastica
