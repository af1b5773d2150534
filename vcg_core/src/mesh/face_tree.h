// SPDX-License-Identifier: GPL-3.0-or-later
// A bounding-volume hierarchy over boxes (a mesh's faces, or the segments of its sharp edges): the
// broad phase of the thickness measure's ray casts (mesh/thickness.cpp) and of the closest-point
// queries that keep a remeshing on its input surface (mesh/surface_projection.h), O(log n) each
// rather than O(n).
#pragma once

#include "mesh/box.h"

#include <elastica/types.h>

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace elastica {

struct BoxTree {
  struct Node {
    Box box;
    int left = -1, right = -1;  // children; -1 at a leaf
    int begin = 0, end = 0;     // the leaf's range of `order`
  };
  std::vector<Node> nodes;
  std::vector<int> order;  // the items' indices, grouped by leaf

  BoxTree() = default;
  explicit BoxTree(const std::vector<Box>& boxes) : items_(&boxes) {
    const int n = static_cast<int>(boxes.size());
    order.resize(n);
    std::iota(order.begin(), order.end(), 0);
    centre_.resize(n);
    for (int i = 0; i < n; ++i) centre_[i] = 0.5 * (boxes[i].lo + boxes[i].hi);
    if (n > 0) build(0, n);
    centre_.clear();
    items_ = nullptr;
  }

  /// The item nearest to p by `distance2(item, p)` (squared, ≥ the squared distance from p to the
  /// item's box; infinity to skip an item), and that squared distance: depth first, the nearer
  /// child first, skipping every box no nearer than the best so far. (-1, infinity) if none.
  template <class Distance2>
  std::pair<int, double> nearest(const Vec3& p, Distance2&& distance2) const {
    int bestItem = -1;
    double best = std::numeric_limits<double>::infinity();
    if (nodes.empty()) return {bestItem, best};
    std::array<std::pair<double, int>, 128> pending;  // one pending node a level, plus one
    int top = 0;
    pending[top++] = {boxDistance2(p, nodes[0].box), 0};
    while (top > 0) {
      const auto [bound, n] = pending[--top];
      if (bound >= best) continue;
      const Node& node = nodes[n];
      if (node.left < 0) {
        for (int i = node.begin; i < node.end; ++i) {
          const double d = distance2(order[i], p);
          if (d < best || (d == best && order[i] < bestItem)) best = d, bestItem = order[i];
        }
        continue;
      }
      std::pair<double, int> nearer{boxDistance2(p, nodes[node.left].box), node.left},
          farther{boxDistance2(p, nodes[node.right].box), node.right};
      if (farther.first < nearer.first) std::swap(nearer, farther);
      if (farther.first < best) pending[top++] = farther;
      if (nearer.first < best) pending[top++] = nearer;
    }
    return {bestItem, best};
  }

  /// Squared distance from p to the box (0 inside).
  static double boxDistance2(const Vec3& p, const Box& b) { return (b.lo - p).cwiseMax(p - b.hi).cwiseMax(0.0).squaredNorm(); }

 private:
  static constexpr int kLeafItems = 4;

  int build(int begin, int end) {
    const int id = static_cast<int>(nodes.size());
    nodes.emplace_back();
    Box box, centres;
    for (int i = begin; i < end; ++i) {
      box.add((*items_)[order[i]].lo);
      box.add((*items_)[order[i]].hi);
      centres.add(centre_[order[i]]);
    }
    nodes[id].box = box;
    if (end - begin <= kLeafItems) {
      nodes[id].begin = begin;
      nodes[id].end = end;
      return id;
    }
    int axis = 0;
    const Vec3 extent = centres.hi - centres.lo;
    if (extent.y() > extent[axis]) axis = 1;
    if (extent.z() > extent[axis]) axis = 2;
    const int mid = begin + (end - begin) / 2;
    // Ties broken by index, so the tree (and nothing else depends on it) is the same on every run.
    std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end, [&](int a, int b) {
      return centre_[a][axis] < centre_[b][axis] || (centre_[a][axis] == centre_[b][axis] && a < b);
    });
    const int left = build(begin, mid);
    const int right = build(mid, end);
    nodes[id].left = left;
    nodes[id].right = right;
    return id;
  }

  const std::vector<Box>* items_ = nullptr;  // during the build only
  std::vector<Vec3> centre_;
};

/// The boxes of a mesh's faces, in face order.
inline std::vector<Box> faceBoxes(const TriMesh& mesh) {
  std::vector<Box> boxes;
  boxes.reserve(mesh.faces.size());
  for (const Face& t : mesh.faces) boxes.push_back(boxOf(mesh, t));
  return boxes;
}

}  // namespace elastica
