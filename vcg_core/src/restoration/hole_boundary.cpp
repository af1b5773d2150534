#include "restoration/hole_boundary.h"

#include <algorithm>
#include <cmath>

namespace elastica {

std::vector<HoleLoop> findHoleLoops(const Topology& topo) {
  // Hole half-edges: for a boundary edge a → b in its face (a, b, c), the hole runs b → a.
  struct HoleEdge {
    int from, to, outside;
  };
  std::vector<HoleEdge> edges;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    if (!topo.isBoundaryEdge(e)) continue;
    const int c = topo.edgeOppositeCorners(e)[0], f = c / 3, k = c % 3;
    const Face& t = topo.faces()[f];
    edges.push_back({t[(k + 2) % 3], t[(k + 1) % 3], t[k]});
  }
  std::sort(edges.begin(), edges.end(),
            [](const HoleEdge& x, const HoleEdge& y) { return x.from != y.from ? x.from < y.from : x.to < y.to; });
  // Outgoing hole edges of each vertex: [first[v], first[v + 1]) in `edges`.
  std::vector<int> first(topo.vertexCount() + 1, 0);
  for (const HoleEdge& h : edges) ++first[h.from + 1];
  for (int v = 0; v < topo.vertexCount(); ++v) first[v + 1] += first[v];

  std::vector<char> used(edges.size(), 0);
  std::vector<HoleLoop> loops;
  for (size_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    HoleLoop loop;
    std::size_t cur = start;
    for (;;) {
      used[cur] = 1;
      loop.vertices.push_back(edges[cur].from);
      loop.outside.push_back(edges[cur].outside);
      const int v = edges[cur].to;
      if (v == edges[start].from) break;
      // At a vertex with several outgoing hole edges (a pinch), take the first unused one.
      std::size_t next = edges.size();
      for (int k = first[v]; k < first[v + 1]; ++k) {
        if (!used[k]) {
          next = static_cast<std::size_t>(k);
          break;
        }
      }
      if (next == edges.size()) break;  // cannot happen on a valid mesh: every boundary vertex balances
      cur = next;
    }
    std::vector<int> sorted = loop.vertices;
    std::sort(sorted.begin(), sorted.end());
    loop.pinched = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
    loops.push_back(std::move(loop));
  }
  return loops;
}

namespace {
double angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }
}  // namespace

double borderCornerBoundDegrees(const std::vector<Vec3>& positions, const Topology& topo, const HoleLoop& loop) {
  const double pi = std::acos(-1.0);
  double bound = pi;
  const int n = loop.edgeCount();
  for (int i = 0; i < n; ++i) {
    const int v = loop.vertices[i], u = loop.vertices[(i + n - 1) % n], w = loop.vertices[(i + 1) % n];
    double meshAngle = 0;  // what the mesh's own faces span at v
    for (int k = topo.cornerBegin(v); k < topo.cornerEnd(v); ++k) {
      const int c = topo.corner(k), f = c / 3, j = c % 3;
      const Face& t = topo.faces()[f];
      meshAngle += angleBetween(positions[t[(j + 1) % 3]] - positions[v], positions[t[(j + 2) % 3]] - positions[v]);
    }
    if (2 * pi - meshAngle >= pi) continue;  // a reflex corner of the hole: a patch fans it out
    bound = std::min(bound, angleBetween(positions[u] - positions[v], positions[w] - positions[v]));
  }
  return bound * 180 / pi;
}

}  // namespace elastica
