// SPDX-License-Identifier: GPL-3.0-or-later
// Holes cut the way scans lose surface, for the restoration's tests and benchmarks: a geodesic
// disc around a point (one hole however the surface bends, where a ball would also cut through a
// nearby ear or leg), as many faces as give its border a requested number of edges; the faces cut
// away are kept as the truth a restored patch is scored against.
#pragma once

#include "surface_distance.h"

#include <elastica/types.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace elastica::test {

struct Cut {
  TriMesh holed, truth;
  int borderEdges = 0;
};

// Faces ordered by their geodesic distance from the vertex nearest `center` (Dijkstra along edges;
// a face is as far as its farthest vertex): cutting a prefix of this order cuts a geodesic disc,
// one hole however the surface bends (a ball would also cut through a nearby ear or leg).
inline std::vector<int> facesByDistance(const TriMesh& full, const Vec3& center) {
  const int nv = full.vertexCount();
  std::vector<std::vector<std::pair<int, double>>> edges(nv);
  for (const Face& t : full.faces)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const double l = (full.positions[a] - full.positions[b]).norm();
      edges[a].emplace_back(b, l);
      edges[b].emplace_back(a, l);
    }
  int seed = 0;
  for (int v = 1; v < nv; ++v)
    if ((full.positions[v] - center).squaredNorm() < (full.positions[seed] - center).squaredNorm()) seed = v;
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>> queue;
  dist[seed] = 0;
  queue.emplace(0.0, seed);
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    for (const auto& [w, l] : edges[v])
      if (d + l < dist[w]) queue.emplace(dist[w] = d + l, w);
  }
  std::vector<double> key(full.faces.size());
  for (std::size_t f = 0; f < full.faces.size(); ++f)
    key[f] = std::max({dist[full.faces[f][0]], dist[full.faces[f][1]], dist[full.faces[f][2]]});
  std::vector<int> order(full.faces.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  return order;
}

// The first `count` faces of `order` are cut away.
inline Cut cutFaces(const TriMesh& full, const std::vector<int>& order, int count) {
  const int nf = full.faceCount();
  std::vector<std::uint8_t> removed(nf, 0), kept(nf, 1);
  for (int i = 0; i < count; ++i) {
    removed[order[i]] = 1;
    kept[order[i]] = 0;
  }
  // Faces by edge (sorted (edge key, face) pairs): two faces per edge on a closed manifold mesh.
  std::vector<std::pair<long long, int>> byEdge;
  byEdge.reserve(3 * static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f) {
    const Face& t = full.faces[f];
    for (int k = 0; k < 3; ++k) {
      const long long a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
      byEdge.emplace_back(a * full.vertexCount() + b, f);
    }
  }
  std::sort(byEdge.begin(), byEdge.end());
  // A small kept piece enclosed by the cut (the ordering leaves single faces behind where the
  // distance field is flat) would be an island inside the hole: cut it too. Pieces as large as the
  // cut itself (a cut through a neck) stay.
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t i = 1; i < byEdge.size(); ++i)
    if (byEdge[i].first == byEdge[i - 1].first && kept[byEdge[i].second] && kept[byEdge[i - 1].second])
      parent[root(byEdge[i].second)] = root(byEdge[i - 1].second);
  std::vector<int> size(nf, 0);
  for (int f = 0; f < nf; ++f)
    if (kept[f]) ++size[root(f)];
  const int largest = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
  for (int f = 0; f < nf; ++f)
    if (kept[f] && root(f) != largest && size[root(f)] < count) kept[f] = 0, removed[f] = 1;
  // Border edges of the cut: edges between a removed and a kept face.
  Cut cut;
  for (std::size_t i = 1; i < byEdge.size(); ++i)
    if (byEdge[i].first == byEdge[i - 1].first && kept[byEdge[i].second] != kept[byEdge[i - 1].second]) ++cut.borderEdges;
  cut.holed = bench::facesOf(full, kept);
  cut.truth = bench::facesOf(full, removed);
  return cut;
}

// The geodesic disc whose border has about `edges` edges (bisection on the number of faces cut:
// the border grows with it, not strictly).
inline Cut cutWithBorder(const TriMesh& full, const std::vector<int>& order, int edges) {
  int lo = 1, hi = full.faceCount() / 2;
  Cut best;
  best.borderEdges = -1;
  while (lo <= hi && std::abs(best.borderEdges - edges) > edges / 50) {
    const int mid = (lo + hi) / 2;
    Cut c = cutFaces(full, order, mid);
    (c.borderEdges < edges ? lo : hi) = c.borderEdges < edges ? mid + 1 : mid - 1;
    if (best.borderEdges < 0 || std::abs(c.borderEdges - edges) < std::abs(best.borderEdges - edges)) best = std::move(c);
  }
  return best;
}

}  // namespace elastica::test
