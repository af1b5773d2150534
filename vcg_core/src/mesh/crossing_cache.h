// SPDX-License-Identifier: GPL-3.0-or-later
// The embedding guard's crossing test, repeated on a mesh where only some faces move: the faces
// that do not move (a selected region's obstacles, its fixed rings) are binned into a grid once and
// kept; each call bins only the moving faces and tests them against each other and against the
// kept grid. The answers are selfIntersectingFaces' and selfIntersects' (mesh/self_intersection.h)
// for the same mesh and flags, whatever the cache held before.
#pragma once

#include <elastica/types.h>

#include "mesh/box.h"

#include <array>
#include <cstdint>
#include <vector>

namespace elastica {

class CrossingCache {
 public:
  /// selfIntersectingFaces(mesh, &moving).
  std::vector<int> crossingFaces(const TriMesh& mesh, const std::vector<std::uint8_t>& moving);
  /// selfIntersects(mesh, &moving).
  bool crosses(const TriMesh& mesh, const std::vector<std::uint8_t>& moving);
  /// How many times the kept grid was built: once per connectivity and flags, and again whenever a
  /// face that was not flagged moved or was rewritten.
  int builds() const { return builds_; }

 private:
  using Cell = std::array<std::int64_t, 3>;
  // The kept grid still describes `mesh`: the same face count and flags, and every unflagged face
  // with the corners and corner positions it had when the grid was built. The flagged faces may
  // move and be rewritten (edge flips between moving vertices) freely: they are binned per call.
  bool keeps(const TriMesh& mesh, const std::vector<std::uint8_t>& moving) const;
  void build(const TriMesh& mesh, const std::vector<std::uint8_t>& moving);
  Cell cellOf(const Vec3& p) const;
  // The slot of a cell, added (with no kept face) if new.
  int slotOf(std::uint64_t key);
  std::size_t hashOf(std::uint64_t key) const;
  void grow();
  template <class Visit>
  void candidatePairs(const TriMesh& mesh, const std::vector<std::uint8_t>& moving, Visit visit);

  int builds_ = 0;
  // What the kept grid was built from.
  std::vector<std::uint8_t> moving_;
  std::vector<Face> faces_;             // every face as it was; only the unflagged ones are checked
  std::vector<int> keptVertices_;       // the unflagged faces' corners, ascending
  std::vector<Vec3> keptPositions_;     // and their positions
  // The grid: cells of size cell_ from origin_, found by key in an open-addressing table.
  Vec3 origin_ = Vec3::Zero();
  double cell_ = 1;
  std::vector<std::uint64_t> tableKey_;  // kNoKey where empty
  std::vector<int> tableSlot_;
  int tableShift_ = 64;                  // 64 − log2 of the table's size
  std::vector<std::uint64_t> slotKey_;
  std::vector<int> keptStart_, keptFaces_;  // per slot with kept faces (slot < keptSlots_): its faces, ascending
  int keptSlots_ = 0;
  std::vector<int> largeKept_;          // unflagged faces too large to bin
  std::vector<Box> boxes_;              // per face: the kept faces' from the build, the moving ones' per call
  std::vector<Cell> lo_, hi_;           // per face, likewise
  // Per moving face, the slots of its cells at the last call (slotsKnown_: since the build).
  std::vector<int> slotStart_, slots_, nextSlotStart_, nextSlots_;
  bool slotsKnown_ = false;
  // Per call.
  std::vector<int> localOf_;            // per slot: its index among this call's cells, or -1
  std::vector<int> touched_, start_, entrySlot_, entryFace_, sortedFace_;
};

}  // namespace elastica
