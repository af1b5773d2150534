// SPDX-License-Identifier: GPL-3.0-or-later
#include "restoration/hole_pinches.h"

#include <algorithm>
#include <numeric>
#include <optional>

namespace elastica {
namespace {

bool samePoint(const Vec3& a, const Vec3& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

// The first pair i < j (in loop order) of distinct vertices at one position that may be welded.
std::optional<std::pair<int, int>> findPinch(const HoleLoop& loop, const std::vector<Vec3>& positions,
                                             const std::function<bool(int, int)>& weld) {
  const int n = loop.edgeCount();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int i) { return positions[loop.vertices[i]]; };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const Vec3 &p = key(a), &q = key(b);
    if (p[0] != q[0]) return p[0] < q[0];
    if (p[1] != q[1]) return p[1] < q[1];
    if (p[2] != q[2]) return p[2] < q[2];
    return a < b;
  });
  for (int s = 1; s < n; ++s) {
    const int i = order[s - 1], j = order[s];
    if (!samePoint(key(i), key(j)) || loop.vertices[i] == loop.vertices[j]) continue;
    const int a = loop.vertices[i], b = loop.vertices[j];
    if (weld(std::min(a, b), std::max(a, b))) return std::make_pair(i, j);
  }
  return std::nullopt;
}

// Loop positions [from, to) (cyclically) as a loop whose first vertex is `first`.
HoleLoop part(const HoleLoop& loop, int from, int to, int first) {
  const int n = loop.edgeCount();
  HoleLoop out;
  for (int k = from; k != to; k = (k + 1) % n) {
    out.vertices.push_back(loop.vertices[k]);
    out.outside.push_back(loop.outside[k]);
  }
  out.vertices.front() = first;
  return out;
}

}  // namespace

PinchSplit splitAtPinches(const HoleLoop& loop, const std::vector<Vec3>& positions,
                          const std::function<bool(int, int)>& weld) {
  PinchSplit out;
  std::vector<HoleLoop> pending{loop};
  while (!pending.empty()) {
    HoleLoop current = std::move(pending.back());
    pending.pop_back();
    const auto pinch = current.pinched ? std::nullopt : findPinch(current, positions, weld);
    if (!pinch) {
      out.loops.push_back(std::move(current));
      continue;
    }
    const auto [i, j] = *pinch;
    // The copy with the smaller index stays: fewer vertices move down when the other is dropped.
    const int kept = std::min(current.vertices[i], current.vertices[j]);
    const int removed = std::max(current.vertices[i], current.vertices[j]);
    out.welds.push_back({kept, removed});
    // i → … → j−1 → (j ≡ i) and j → … → i−1 → (i): each closes at the welded point, and each
    // keeps the outside faces of its own edges.
    for (HoleLoop piece : {part(current, i, j, kept), part(current, j, i, kept)}) {
      if (piece.edgeCount() >= 3) pending.push_back(std::move(piece));
    }
  }
  return out;
}

}  // namespace elastica
