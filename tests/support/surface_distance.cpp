// SPDX-License-Identifier: GPL-3.0-or-later
#include "surface_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

namespace elastica::bench {
namespace {

// Squared distance from p to triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
double pointTriangleDistance2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).squaredNorm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).squaredNorm();
  const double denom = 1 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).squaredNorm();
}

// Squared distance from p to the nearest point of the box [lo, hi] (0 inside): no face in the box
// can be nearer than that.
double boxDistance2(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).squaredNorm();
}

// A bounding-box tree over a mesh's faces, for nearest-face queries: the exact nearest face, as
// brute force would find it, in time that grows with the patch, not with patch × truth (a
// 2,000-edge hole's patch and truth hold ~10^5 faces each). A tree rather than a uniform grid
// because a grid's search grows with the cube of the distance in cells, and a patch that wraps
// around a model has points far from the truth; the tree's cost barely depends on the distance.
class FaceTree {
 public:
  explicit FaceTree(const TriMesh& m) : m_(m), order_(m.faces.size()) {
    std::iota(order_.begin(), order_.end(), 0);
    centroids_.reserve(m.faces.size());
    for (const Face& f : m.faces) centroids_.push_back((m.positions[f[0]] + m.positions[f[1]] + m.positions[f[2]]) / 3);
    if (!order_.empty()) build(0, static_cast<int>(order_.size()));
  }

  // Squared distance from p to the nearest face (infinity for a mesh without faces): depth first,
  // the nearer child first, skipping every box no nearer than the best face found so far.
  double nearest2(const Vec3& p) const {
    double best = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) return best;
    // At most one pending node a level, plus one; median splits keep the depth at log2(faces).
    std::array<std::pair<double, int>, 64> pending;
    int top = 0;
    pending[top++] = {boxDistance2(p, nodes_[0].lo, nodes_[0].hi), 0};
    while (top > 0) {
      const auto [bound, n] = pending[--top];
      if (bound >= best) continue;  // best may have dropped since this node was pushed
      const Node& node = nodes_[n];
      if (node.right < 0) {
        for (int i = node.begin; i < node.end; ++i) {
          const Face& g = m_.faces[order_[i]];
          best = std::min(best, pointTriangleDistance2(p, m_.positions[g[0]], m_.positions[g[1]], m_.positions[g[2]]));
        }
        continue;
      }
      std::pair<double, int> nearer{boxDistance2(p, nodes_[n + 1].lo, nodes_[n + 1].hi), n + 1},
          farther{boxDistance2(p, nodes_[node.right].lo, nodes_[node.right].hi), node.right};
      if (farther.first < nearer.first) std::swap(nearer, farther);
      // The nearer child is popped first: it most likely holds the nearest face, and the bound it
      // sets lets the farther one be skipped.
      if (farther.first < best) pending[top++] = farther;
      if (nearer.first < best) pending[top++] = nearer;
    }
    return best;
  }

 private:
  static constexpr int kLeafFaces = 4;  // small leaves: few exact distances per box reached

  struct Node {
    Vec3 lo, hi;         // the bounding box of the node's faces
    int begin, end;      // the node's faces: order_[begin, end)
    int right = -1;      // the right child, or -1 for a leaf; the left child is the next node
  };

  // Makes the node over order_[begin, end) and, below it, its subtree (depth first, so that the
  // left child follows its parent); returns the node's index.
  int build(int begin, int end) {
    const int n = static_cast<int>(nodes_.size());
    Vec3 lo = m_.positions[m_.faces[order_[begin]][0]], hi = lo, clo = centroids_[order_[begin]], chi = clo;
    for (int i = begin; i < end; ++i) {
      for (int v : m_.faces[order_[i]]) {
        lo = lo.cwiseMin(m_.positions[v]);
        hi = hi.cwiseMax(m_.positions[v]);
      }
      clo = clo.cwiseMin(centroids_[order_[i]]);
      chi = chi.cwiseMax(centroids_[order_[i]]);
    }
    nodes_.push_back({lo, hi, begin, end});
    if (end - begin <= kLeafFaces) return n;
    // Halve the faces at the median centroid along the axis where the centroids spread most:
    // balanced (hence shallow) whatever the faces' sizes, and compact boxes on a surface.
    int axis = 0;
    (chi - clo).maxCoeff(&axis);
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](int f, int g) { return centroids_[f][axis] < centroids_[g][axis]; });
    build(begin, mid);
    const int right = build(mid, end);
    nodes_[n].right = right;  // not through a reference taken before: the recursion grows nodes_
    return n;
  }

  const TriMesh& m_;
  std::vector<int> order_;  // face indices, grouped by node
  std::vector<Vec3> centroids_;
  std::vector<Node> nodes_;
};

}  // namespace

DistanceStats sampledDistance(const TriMesh& a, const TriMesh& b, int perEdge) {
  if (b.faces.empty()) return {};
  const FaceTree tree(b);
  double sum = 0, worst = 0;
  long count = 0;
  for (const Face& f : a.faces) {
    for (int i = 0; i <= perEdge; ++i) {
      for (int j = 0; i + j <= perEdge; ++j) {
        const double u = double(i) / perEdge, v = double(j) / perEdge;
        const Vec3 p = (1 - u - v) * a.positions[f[0]] + u * a.positions[f[1]] + v * a.positions[f[2]];
        const double best = tree.nearest2(p);
        sum += best;
        worst = std::max(worst, best);
        ++count;
      }
    }
  }
  return {count ? std::sqrt(sum / count) : 0, std::sqrt(worst)};
}

TriMesh facesOf(const TriMesh& m, const std::vector<std::uint8_t>& keep) {
  TriMesh out;
  std::vector<int> index(m.positions.size(), -1);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!keep[f]) continue;
    Face t;
    for (int k = 0; k < 3; ++k) {
      int& i = index[m.faces[f][k]];
      if (i < 0) {
        i = out.vertexCount();
        out.positions.push_back(m.positions[m.faces[f][k]]);
      }
      t[k] = i;
    }
    out.faces.push_back(t);
  }
  return out;
}

}  // namespace elastica::bench
