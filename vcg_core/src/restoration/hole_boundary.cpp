#include "restoration/hole_boundary.h"

#include <elastica/errors.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace elastica {

std::vector<HoleLoop> findHoleLoops(const Topology& topo) {
  // Hole half-edges: for a boundary edge a → b in its face (a, b, c), the hole runs b → a.
  std::vector<HoleHalfEdge> edges;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    if (!topo.isBoundaryEdge(e)) continue;
    const int c = topo.edgeOppositeCorners(e)[0], f = c / 3, k = c % 3;
    const Face& t = topo.faces()[f];
    edges.push_back({t[(k + 2) % 3], t[(k + 1) % 3], t[k]});
  }
  return findHoleLoops(std::move(edges));
}

std::vector<HoleLoop> findHoleLoops(std::vector<HoleHalfEdge> edges) {
  std::sort(edges.begin(), edges.end(),
            [](const HoleHalfEdge& x, const HoleHalfEdge& y) { return x.from != y.from ? x.from < y.from : x.to < y.to; });
  // Outgoing hole edges of vertex v: the run of `edges` from `from` = v on.
  auto firstFrom = [&](int v) {
    return static_cast<std::size_t>(
        std::lower_bound(edges.begin(), edges.end(), v, [](const HoleHalfEdge& h, int x) { return h.from < x; }) - edges.begin());
  };

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
      for (std::size_t k = firstFrom(v); k < edges.size() && edges[k].from == v; ++k) {
        if (!used[k]) {
          next = k;
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

void checkFaceIndices(const TriMesh& mesh) {
  const int nv = mesh.vertexCount();
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Face& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k) {
      if (t[k] < 0 || t[k] >= nv) {
        throw InvalidInputError("fill: face " + std::to_string(f) + " references vertex " + std::to_string(t[k]) +
                                ", outside [0, " + std::to_string(nv) + ")");
      }
    }
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      throw InvalidInputError("fill: face " + std::to_string(f) + " repeats vertex " + std::to_string(t[0] == t[1] || t[0] == t[2] ? t[0] : t[1]));
  }
}

std::vector<HoleHalfEdge> boundaryHalfEdges(const TriMesh& mesh, const VertexFaceIndex& adjacency) {
  std::vector<HoleHalfEdge> edges;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Face& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k) {
      // Edge a → b of face f: the faces around a that also use b share it.
      const int a = t[k], b = t[(k + 1) % 3];
      int shared = 0;
      for (int g : adjacency[a]) {
        const Face& s = mesh.faces[g];
        shared += s[0] == b || s[1] == b || s[2] == b;
      }
      if (shared > 2) {
        throw InvalidInputError("fill: non-manifold edge between vertices " + std::to_string(std::min(a, b)) + " and " +
                                std::to_string(std::max(a, b)) + " (shared by " + std::to_string(shared) + " faces)");
      }
      if (shared == 1) edges.push_back({b, a, t[(k + 2) % 3]});  // the hole runs against the face
    }
  }
  return edges;
}

namespace {
double angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }
}  // namespace

double cornerAngleSum(const TriMesh& mesh, VertexFaceIndex::Range faces, int v) {
  double sum = 0;
  for (int f : faces) {
    const Face& t = mesh.faces[f];
    const int j = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    sum += angleBetween(mesh.positions[t[(j + 1) % 3]] - mesh.positions[v], mesh.positions[t[(j + 2) % 3]] - mesh.positions[v]);
  }
  return sum;
}

double borderCornerBoundDegrees(const std::vector<Vec3>& positions, const HoleLoop& loop, const std::function<double(int)>& meshAngle) {
  const double pi = std::acos(-1.0);
  double bound = pi;
  const int n = loop.edgeCount();
  for (int i = 0; i < n; ++i) {
    const int v = loop.vertices[i], u = loop.vertices[(i + n - 1) % n], w = loop.vertices[(i + 1) % n];
    if (2 * pi - meshAngle(v) >= pi) continue;  // a reflex corner of the hole: a patch fans it out
    bound = std::min(bound, angleBetween(positions[u] - positions[v], positions[w] - positions[v]));
  }
  return bound * 180 / pi;
}

double borderCornerBoundDegrees(const std::vector<Vec3>& positions, const Topology& topo, const HoleLoop& loop) {
  return borderCornerBoundDegrees(positions, loop, [&](int v) {
    double meshAngle = 0;  // what the mesh's own faces span at v
    for (int k = topo.cornerBegin(v); k < topo.cornerEnd(v); ++k) {
      const int c = topo.corner(k), f = c / 3, j = c % 3;
      const Face& t = topo.faces()[f];
      meshAngle += angleBetween(positions[t[(j + 1) % 3]] - positions[v], positions[t[(j + 2) % 3]] - positions[v]);
    }
    return meshAngle;
  });
}

}  // namespace elastica
