// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/vertex_fans.h>

#include <algorithm>
#include <numeric>

namespace elastica {

void FanJoin::reset(int n) {
  parent_.resize(static_cast<std::size_t>(n));
  std::iota(parent_.begin(), parent_.end(), 0);
}

int FanJoin::root(int i) {
  while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
  return i;
}

void FanJoin::join(int i, int j) {
  const int a = root(i), b = root(j);
  if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // a fan's root is its first face
}

int FanJoin::number(std::vector<int>& fan) {
  const int n = static_cast<int>(parent_.size());
  fan.resize(parent_.size());
  // A fan's root comes before its other faces, so it is numbered first.
  int fans = 0;
  for (int i = 0; i < n; ++i) {
    const int r = root(i);
    fan[i] = r == i ? fans++ : fan[r];
  }
  return fans;
}

int fansAt(const std::vector<Face>& faces, const int* corners, std::size_t count, std::vector<int>& fan,
           FanScratch& scratch) {
  const int n = static_cast<int>(count);
  // Two faces that hold the same spoke (edge at v) are one fan: sorted by the spoke's other end,
  // the faces of an edge are neighbours.
  auto& spokes = scratch.spokes;
  spokes.clear();
  for (int i = 0; i < n; ++i) {
    const int c = corners[i], f = c / 3, k = c % 3;
    spokes.emplace_back(faces[f][(k + 1) % 3], i);
    spokes.emplace_back(faces[f][(k + 2) % 3], i);
  }
  std::sort(spokes.begin(), spokes.end());
  scratch.join.reset(n);
  for (std::size_t s = 1; s < spokes.size(); ++s)
    if (spokes[s].first == spokes[s - 1].first) scratch.join.join(spokes[s].second, spokes[s - 1].second);
  return scratch.join.number(fan);
}

}  // namespace elastica
