// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/crossing_cache.h"
#include "mesh/self_intersection.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace elastica {
namespace {

constexpr std::uint64_t kNoKey = ~std::uint64_t(0);
// Cell coordinates are offset so that a moving face may leave the box the grid was built on
// (by up to 2^20 cells) and still get its own cells; beyond, they are clamped, which keeps every
// pair whose boxes meet (clamping is monotone) and only makes such faces share cells.
constexpr std::int64_t kCellOffset = std::int64_t(1) << 20, kCellLimit = (std::int64_t(1) << 21) - 1;

// The cell's size in mean face boxes (the largest side of a face's box, averaged over the faces).
// The plain test's grid uses 1; here fewer, larger cells made the per-call test cheaper (fewer
// entries per moving face against a few more candidate pairs per cell).
constexpr double kCellPerMeanFace = 1.5;

std::uint64_t keyOf(std::int64_t i, std::int64_t j, std::int64_t k) { return std::uint64_t((i << 42) | (j << 21) | k); }

std::int64_t cellCount(const std::array<std::int64_t, 3>& lo, const std::array<std::int64_t, 3>& hi) {
  return (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
}

}  // namespace

CrossingCache::Cell CrossingCache::cellOf(const Vec3& p) const {
  Cell c;
  for (int axis = 0; axis < 3; ++axis) {
    const double at = std::floor((p[axis] - origin_[axis]) / cell_) + static_cast<double>(kCellOffset);
    c[axis] = static_cast<std::int64_t>(std::clamp(at, 0.0, static_cast<double>(kCellLimit)));
  }
  return c;
}

bool CrossingCache::keeps(const TriMesh& mesh, const std::vector<std::uint8_t>& moving) const {
  if (builds_ == 0 || mesh.faces.size() != faces_.size() || moving != moving_) return false;
  for (std::size_t f = 0; f < faces_.size(); ++f)
    if (!moving_[f] && mesh.faces[f] != faces_[f]) return false;
  for (std::size_t i = 0; i < keptVertices_.size(); ++i)
    if (keptVertices_[i] >= mesh.vertexCount() || mesh.positions[keptVertices_[i]] != keptPositions_[i]) return false;
  return true;
}

void CrossingCache::grow() {
  const std::size_t capacity = std::max<std::size_t>(1024, 4 * slotKey_.size());
  std::size_t size = 1;
  while (size < capacity) size *= 2;
  tableKey_.assign(size, kNoKey);
  tableSlot_.assign(size, -1);
  tableShift_ = 64;
  for (std::size_t n = size; n > 1; n /= 2) --tableShift_;
  const std::size_t mask = size - 1;
  for (std::size_t s = 0; s < slotKey_.size(); ++s) {
    std::size_t h = hashOf(slotKey_[s]);
    while (tableKey_[h] != kNoKey) h = (h + 1) & mask;
    tableKey_[h] = slotKey_[s];
    tableSlot_[h] = static_cast<int>(s);
  }
}

// Fibonacci hashing: the product's top bits depend on every bit of the key (its low bits would
// ignore a cell's first coordinates).
std::size_t CrossingCache::hashOf(std::uint64_t key) const {
  return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> tableShift_);
}

int CrossingCache::slotOf(std::uint64_t key) {
  const std::size_t mask = tableKey_.size() - 1;
  std::size_t h = hashOf(key);
  for (; tableKey_[h] != kNoKey; h = (h + 1) & mask)
    if (tableKey_[h] == key) return tableSlot_[h];
  const int slot = static_cast<int>(slotKey_.size());
  slotKey_.push_back(key);
  localOf_.push_back(-1);
  if (2 * slotKey_.size() > tableKey_.size()) {
    grow();
  } else {
    tableKey_[h] = key;
    tableSlot_[h] = slot;
  }
  return slot;
}

void CrossingCache::build(const TriMesh& mesh, const std::vector<std::uint8_t>& moving) {
  ++builds_;
  const int nf = mesh.faceCount();
  moving_ = moving;
  faces_ = mesh.faces;
  boxes_.resize(nf);
  lo_.resize(nf);
  hi_.resize(nf);
  // Cells of kCellPerMeanFace times the mean face box over every face, from the box of all faces;
  // at most 2^20 cells across it.
  Box all;
  double extentSum = 0;
  for (int f = 0; f < nf; ++f) {
    boxes_[f] = boxOf(mesh, mesh.faces[f]);
    all.lo = all.lo.cwiseMin(boxes_[f].lo);
    all.hi = all.hi.cwiseMax(boxes_[f].hi);
    extentSum += (boxes_[f].hi - boxes_[f].lo).maxCoeff();
  }
  origin_ = nf > 0 ? all.lo : Vec3::Zero();
  const double span = nf > 0 ? (all.hi - all.lo).maxCoeff() : 0.0;
  cell_ = std::max({nf > 0 ? kCellPerMeanFace * extentSum / nf : 0.0, span / static_cast<double>(kCellOffset), 1e-300});

  keptVertices_.clear();
  for (int f = 0; f < nf; ++f)
    if (!moving_[f]) keptVertices_.insert(keptVertices_.end(), mesh.faces[f].begin(), mesh.faces[f].end());
  std::sort(keptVertices_.begin(), keptVertices_.end());
  keptVertices_.erase(std::unique(keptVertices_.begin(), keptVertices_.end()), keptVertices_.end());
  keptPositions_.resize(keptVertices_.size());
  for (std::size_t i = 0; i < keptVertices_.size(); ++i) keptPositions_[i] = mesh.positions[keptVertices_[i]];

  // The kept faces' entries, grouped by cell (slots numbered in key order), each cell's faces ascending.
  std::vector<std::pair<std::uint64_t, int>> entries;
  largeKept_.clear();
  for (int f = 0; f < nf; ++f) {
    if (moving_[f]) continue;
    lo_[f] = cellOf(boxes_[f].lo);
    hi_[f] = cellOf(boxes_[f].hi);
    if (cellCount(lo_[f], hi_[f]) > kMaxCellsPerFace) {
      largeKept_.push_back(f);
      continue;
    }
    for (std::int64_t i = lo_[f][0]; i <= hi_[f][0]; ++i)
      for (std::int64_t j = lo_[f][1]; j <= hi_[f][1]; ++j)
        for (std::int64_t k = lo_[f][2]; k <= hi_[f][2]; ++k) entries.emplace_back(keyOf(i, j, k), f);
  }
  std::sort(entries.begin(), entries.end());
  slotKey_.clear();
  keptStart_.clear();
  keptFaces_.clear();
  for (std::size_t a = 0; a < entries.size(); ++a) {
    if (a == 0 || entries[a].first != entries[a - 1].first) {
      slotKey_.push_back(entries[a].first);
      keptStart_.push_back(static_cast<int>(keptFaces_.size()));
    }
    keptFaces_.push_back(entries[a].second);
  }
  keptStart_.push_back(static_cast<int>(keptFaces_.size()));
  keptSlots_ = static_cast<int>(slotKey_.size());
  localOf_.assign(slotKey_.size(), -1);
  slotsKnown_ = false;
  grow();
}

// Calls visit(f, g) (f < g) for each pair of faces with a flagged face whose boxes meet, until
// visit returns true: in the first cell both cover (so once), moving against moving and moving
// against kept; faces too large to bin against every face.
template <class Visit>
void CrossingCache::candidatePairs(const TriMesh& mesh, const std::vector<std::uint8_t>& moving, Visit visit) {
  if (!keeps(mesh, moving)) build(mesh, moving);
  const int nf = mesh.faceCount();
  if (nf < 2) return;
  auto test = [&](int f, int g) { return boxes_[f].meets(boxes_[g]) && visit(std::min(f, g), std::max(f, g)); };
  auto firstCommonCell = [&](int f, int g) {
    return keyOf(std::max(lo_[f][0], lo_[g][0]), std::max(lo_[f][1], lo_[g][1]), std::max(lo_[f][2], lo_[g][2]));
  };
  std::vector<int> largeMoving;
  touched_.clear();
  entrySlot_.clear();
  entryFace_.clear();
  // A moving face whose cell range is the one it had at the last call keeps its cells' slots
  // (a step moves most faces by a fraction of a cell): the table is looked up only where a face
  // entered other cells.
  nextSlotStart_.assign(static_cast<std::size_t>(nf) + 1, 0);
  nextSlots_.clear();
  for (int f = 0; f < nf; ++f) {
    nextSlotStart_[f] = static_cast<int>(nextSlots_.size());
    if (!moving[f]) continue;
    boxes_[f] = boxOf(mesh, mesh.faces[f]);
    const Cell lo = cellOf(boxes_[f].lo), hi = cellOf(boxes_[f].hi);
    const bool sameCells = slotsKnown_ && lo == lo_[f] && hi == hi_[f];
    lo_[f] = lo;
    hi_[f] = hi;
    if (cellCount(lo, hi) > kMaxCellsPerFace) {
      largeMoving.push_back(f);
      continue;
    }
    if (sameCells) {
      nextSlots_.insert(nextSlots_.end(), slots_.begin() + slotStart_[f], slots_.begin() + slotStart_[f + 1]);
    } else {
      for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
        for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
          for (std::int64_t k = lo[2]; k <= hi[2]; ++k) nextSlots_.push_back(slotOf(keyOf(i, j, k)));
    }
    for (int e = nextSlotStart_[f]; e < static_cast<int>(nextSlots_.size()); ++e) {
      const int slot = nextSlots_[e];
      if (localOf_[slot] < 0) localOf_[slot] = static_cast<int>(touched_.size()), touched_.push_back(slot);
      entrySlot_.push_back(localOf_[slot]);
      entryFace_.push_back(f);
    }
  }
  nextSlotStart_[nf] = static_cast<int>(nextSlots_.size());
  slotStart_.swap(nextSlotStart_);
  slots_.swap(nextSlots_);
  slotsKnown_ = true;
  // The moving entries grouped by cell, in the order of the cells' first entry, each cell's faces
  // ascending (a stable counting sort).
  start_.assign(touched_.size() + 1, 0);
  for (int t : entrySlot_) ++start_[t + 1];
  for (std::size_t t = 1; t < start_.size(); ++t) start_[t] += start_[t - 1];
  sortedFace_.resize(entryFace_.size());
  for (std::size_t e = 0; e < entryFace_.size(); ++e) sortedFace_[start_[entrySlot_[e]]++] = entryFace_[e];
  for (std::size_t t = touched_.size(); t > 0; --t) start_[t] = start_[t - 1];
  start_[0] = 0;
  for (int slot : touched_) localOf_[slot] = -1;

  for (std::size_t t = 0; t < touched_.size(); ++t) {
    const int slot = touched_[t];
    const std::uint64_t here = slotKey_[slot];
    for (int x = start_[t]; x < start_[t + 1]; ++x) {
      const int f = sortedFace_[x];
      for (int y = x + 1; y < start_[t + 1]; ++y) {
        const int g = sortedFace_[y];
        if (firstCommonCell(f, g) == here && test(f, g)) return;
      }
      if (slot >= keptSlots_) continue;
      for (int k = keptStart_[slot]; k < keptStart_[slot + 1]; ++k) {
        const int g = keptFaces_[k];
        if (firstCommonCell(f, g) == here && test(f, g)) return;
      }
    }
  }
  for (int g : largeKept_)
    for (int f = 0; f < nf; ++f)
      if (moving[f] && test(f, g)) return;
  std::vector<std::uint8_t> isLargeMoving(largeMoving.empty() ? 0 : nf, 0);
  for (int f : largeMoving) isLargeMoving[f] = 1;
  for (int f : largeMoving)
    for (int g = 0; g < nf; ++g) {
      // Large kept faces were tested above; large moving pairs once, from the smaller index.
      const bool largeKept = !moving[g] && cellCount(lo_[g], hi_[g]) > kMaxCellsPerFace;
      if (g == f || largeKept || (isLargeMoving[g] && g < f)) continue;
      if (test(f, g)) return;
    }
}

std::vector<int> CrossingCache::crossingFaces(const TriMesh& mesh, const std::vector<std::uint8_t>& moving) {
  return facesOfCrossingPairs(mesh, [&](auto visit) { candidatePairs(mesh, moving, visit); });
}

bool CrossingCache::crosses(const TriMesh& mesh, const std::vector<std::uint8_t>& moving) {
  return anyPairCrosses(mesh, [&](auto visit) { candidatePairs(mesh, moving, visit); });
}

}  // namespace elastica
