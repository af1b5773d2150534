// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/topology.h>
#include "mesh/edge_flips.h"
#include "mesh/edge_key.h"
#include "operators/corner_angle.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace elastica {
namespace {

// Flips beyond this much (radians) past π only: avoids flipping back and forth on cocircular quads.
constexpr double kAngleSlack = 1e-6;

// Whether the angles at c and d opposite edge (a, b) certainly sum to less than π: the sign of
// sin(α + β) = sin α sin β (cot α + cot β), with a margin far above rounding. Most edges of a
// patch are comfortably Delaunay; this spares them the two arc tangents of the exact test, and
// decides nothing the exact test would decide otherwise.
bool clearlyDelaunay(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 ca = a - c, cb = b - c, da = a - d, db = b - d;
  const double sinC = ca.cross(cb).norm(), cosC = ca.dot(cb), sinD = da.cross(db).norm(), cosD = da.dot(db);
  return cosC * sinD + cosD * sinC > 1e-9 * (std::abs(cosC) * sinD + std::abs(cosD) * sinC);
}

// The faces on each edge as the flips leave them: the adjacency of the mesh as given (the caller's
// Topology where it is the mesh's, else one built here), and beside it the edges whose faces a
// flip changed ({-1, -1}: flipped away).
class LiveEdges {
 public:
  LiveEdges(const TriMesh& mesh, const Topology* current) {
    if (current && current->vertexCount() == mesh.vertexCount() && current->faces() == mesh.faces) topo_ = current;
    else topo_ = &own_.emplace(mesh.vertexCount(), mesh.faces);
  }
  const Topology& initial() const { return *topo_; }

  // The faces on edge (a, b), in no order; {-1, -1} if there is no such edge, {f, -1} on a border.
  std::array<int, 2> faces(int a, int b) const {
    const auto it = changed_.find(edgeKey(a, b));
    if (it != changed_.end()) return it->second;
    for (int k = topo_->ringBegin(a); k < topo_->ringEnd(a); ++k) {
      if (topo_->ringVertex(k) != b) continue;
      const auto& oc = topo_->edgeOppositeCorners(topo_->ringEdge(k));
      return {oc[0] / 3, oc[1] < 0 ? -1 : oc[1] / 3};
    }
    return {-1, -1};
  }
  bool exists(int a, int b) const { return faces(a, b)[0] >= 0; }

  // Records the flip of edge (a, b) between f0 = (a, b, c) and f1 = (b, a, d) into (c, d).
  void flip(int a, int b, int c, int d, int f0, int f1) {
    auto move = [&](int u, int v, int from, int to) {
      std::array<int, 2> f = faces(u, v);
      for (int& x : f) x = x == from ? to : x;
      changed_[edgeKey(u, v)] = f;
    };
    move(b, c, f0, f1);  // (b, c) leaves f0 for f1, (a, d) leaves f1 for f0
    move(a, d, f1, f0);
    changed_[edgeKey(a, b)] = {-1, -1};
    changed_[edgeKey(c, d)] = {f0, f1};
  }

 private:
  std::optional<Topology> own_;
  const Topology* topo_ = nullptr;
  std::unordered_map<std::uint64_t, std::array<int, 2>> changed_;
};

// Pass by pass, each pass over the edges as they were when it began in increasing (lo, hi) order,
// no face flipped twice in one pass, and no flip to an edge that existed when the pass began or
// that the pass made. The adjacency is built once: an edge that a pass looked at and did not flip
// is not flipped by the next one either unless one of its faces changed or the edge that stopped
// it went away, so after the first pass only the edges of flipped faces and the edges stopped by
// an existing one are looked at again (the same flips in the same order as a pass over every edge
// of a freshly built adjacency, which the restoration's refinement did up to 100 times a patch).
// With `ends` (one byte per vertex), the first pass looks only at the edges between flagged
// vertices: `allowed` refuses the others, and a refused edge changes nothing (a region's piece is
// mostly fixed rings and obstacles, whose edges were most of the pass).
int flipPasses(TriMesh& mesh, const FlipFilter& allowed, int maxPasses, const Topology* current,
               const std::vector<std::uint8_t>* ends) {
  const auto& p = mesh.positions;
  LiveEdges live(mesh, current);
  std::vector<std::pair<int, int>> edges;  // what the pass looks at, (lo, hi) in increasing order
  edges.reserve(live.initial().edgeCount());
  for (int e = 0; e < live.initial().edgeCount(); ++e) {
    const auto& ev = live.initial().edgeVertices(e);
    if (!ends || ((*ends)[ev[0]] && (*ends)[ev[1]])) edges.emplace_back(ev[0], ev[1]);
  }
  std::vector<std::uint8_t> touched(mesh.faces.size(), 0);
  std::vector<int> touchedFaces;
  std::vector<std::pair<int, int>> stopped;  // edges not flipped because their new edge existed
  std::unordered_set<std::uint64_t> removed;  // edges this pass flipped away
  int total = 0;
  for (int pass = 0; pass < maxPasses; ++pass) {
    int flips = 0;
    for (const auto& [lo, hi] : edges) {
      const std::array<int, 2> on = live.faces(lo, hi);
      if (on[0] < 0 || on[1] < 0) continue;  // a border edge, or flipped away by this pass
      const int f0 = std::min(on[0], on[1]), f1 = std::max(on[0], on[1]);
      if (touched[f0] || touched[f1]) continue;
      // f0 = (a, b, c) with c opposite the edge; f1 holds the edge as (b, a) with d opposite.
      const Face& t0 = mesh.faces[f0];
      int k = 0;
      while (t0[k] == lo || t0[k] == hi) ++k;
      const int c = t0[k], a = t0[(k + 1) % 3], b = t0[(k + 2) % 3];
      const Face& t1 = mesh.faces[f1];
      const int d = t1[0] != a && t1[0] != b ? t1[0] : t1[1] != a && t1[1] != b ? t1[1] : t1[2];
      if (c == d || !allowed(a, b, c, d, f0, f1)) continue;
      if (clearlyDelaunay(p[a], p[b], p[c], p[d]) ||
          cornerAngle(p[c], p[a], p[b]) + cornerAngle(p[d], p[a], p[b]) <= M_PI + kAngleSlack)
        continue;
      // Edges this pass created count as existing too: two quads can share their far corners (on
      // a thin tube, c and d are both neighbours of a, b and of a', b'), and the second flip would
      // make c–d an edge of four faces.
      if (live.exists(c, d) || removed.count(edgeKey(c, d))) {
        stopped.emplace_back(lo, hi);
        continue;
      }
      // New faces (a, d, c) and (d, b, c): same orientation as the old pair, or no flip.
      const Vec3 before = (p[b] - p[a]).cross(p[c] - p[a]) + (p[a] - p[b]).cross(p[d] - p[b]);
      const Vec3 n1 = (p[d] - p[a]).cross(p[c] - p[a]), n2 = (p[b] - p[d]).cross(p[c] - p[d]);
      if (n1.dot(before) <= 0 || n2.dot(before) <= 0) continue;
      mesh.faces[f0] = {a, d, c};
      mesh.faces[f1] = {d, b, c};
      live.flip(a, b, c, d, f0, f1);
      removed.insert(edgeKey(a, b));
      touched[f0] = touched[f1] = 1;
      touchedFaces.push_back(f0);
      touchedFaces.push_back(f1);
      ++flips;
    }
    total += flips;
    if (flips == 0) break;
    // The next pass: the edges of the faces this one flipped, and those an existing edge stopped.
    edges.swap(stopped);
    stopped.clear();
    for (int f : touchedFaces) {
      const Face& t = mesh.faces[f];
      for (int j = 0; j < 3; ++j) edges.push_back(std::minmax(t[j], t[(j + 1) % 3]));
      touched[f] = 0;
    }
    touchedFaces.clear();
    removed.clear();
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  }
  return total;
}

}  // namespace

int flipToDelaunay(TriMesh& mesh, const std::vector<std::uint8_t>& movable, int maxPasses) {
  return flipToDelaunay(mesh, nullptr, movable, maxPasses);
}

int flipToDelaunay(TriMesh& mesh, const Topology* current, const std::vector<std::uint8_t>& movable, int maxPasses) {
  return flipPasses(
      mesh, [&](int a, int b, int c, int d, int, int) { return movable[a] && movable[b] && movable[c] && movable[d]; },
      maxPasses, current, &movable);
}

int flipToDelaunay(TriMesh& mesh, const FlipFilter& allowed, int maxPasses) {
  return flipPasses(mesh, allowed, maxPasses, nullptr, nullptr);
}

}  // namespace elastica
