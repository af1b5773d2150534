// SPDX-License-Identifier: GPL-3.0-or-later
// The fans around a vertex: its faces grouped by the edges at the vertex that they share. A manifold
// vertex has one fan (closed around an interior vertex, open at a border); more than one is a
// bow-tie (pinched, non-manifold) vertex. Written once for the topology's count of bow-ties, the
// file checks that split them, and hole filling, which counts them in its input and settles the
// pinches it welds.
#pragma once

#include <elastica/types.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace elastica {

/// Disjoint sets of a vertex's n faces (local numbers 0 … n−1), joined pairwise, then numbered.
/// For callers that already have each edge's faces at hand (the file checks find them while they
/// check the edges); fansAt() finds them from the faces.
class FanJoin {
 public:
  /// n faces, each its own fan. Reuses the storage: a pass over every vertex allocates nothing
  /// per vertex.
  void reset(int n);
  /// Faces i and j share an edge at the vertex: one fan.
  void join(int i, int j);
  /// Sets fan[i] to the fan of face i, fans numbered in order of their first face, and returns
  /// how many there are.
  int number(std::vector<int>& fan);

 private:
  int root(int i);
  std::vector<int> parent_;
};

/// Scratch space for fansAt(), reused between calls.
struct FanScratch {
  FanJoin join;
  std::vector<std::pair<int, int>> spokes;  ///< (other vertex of an edge at v, local face)
};

/// Groups the faces at one vertex, given as its `count` corners (corner c = 3·f + k is vertex
/// faces[f][k]), into fans: sets fan[i] to the fan of corner i's face, fans numbered in order of
/// their first corner in the list, and returns how many there are.
int fansAt(const std::vector<Face>& faces, const int* corners, std::size_t count, std::vector<int>& fan,
           FanScratch& scratch);

}  // namespace elastica
