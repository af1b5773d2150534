// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/self_intersection.h"
#include "mesh/box.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <array>
#include <utility>

namespace elastica {
namespace {

// How many vertices faces f and g share; with exactly one, its positions in f and g.
int sharedVertices(const Face& f, const Face& g, int& inF, int& inG) {
  int n = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (f[i] == g[j]) ++n, inF = i, inG = j;
  return n;
}

// p and q strictly on opposite sides of a plane, given their signed distances (times any factor).
bool opposite(double dp, double dq) { return (dp > 0 && dq < 0) || (dp < 0 && dq > 0); }

// Segment pq, whose ends lie strictly on opposite sides of triangle abc's plane, crosses it
// strictly inside (signed volumes of the same sign).
bool segmentPassesInside(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 d = q - p;
  const double u = d.dot((b - p).cross(c - p));
  const double v = d.dot((c - p).cross(a - p));
  const double w = d.dot((a - p).cross(b - p));
  return (u > 0 && v > 0 && w > 0) || (u < 0 && v < 0 && w < 0);
}

// Segment pq crosses the interior of triangle abc: p and q strictly on opposite sides of its plane
// and the crossing point strictly inside. Touching counts not: a flow meets exact contact with
// probability zero, and counting it would flag fans of valid meshes through round-off.
bool segmentCrossesTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  return opposite(n.dot(p - a), n.dot(q - a)) && segmentPassesInside(p, q, a, b, c);
}

}  // namespace

// Faces sharing no vertex cross if an edge of one crosses the other. Faces sharing one vertex s
// (vcglib's rule): the segment halfway between s and the opposite edge of one face, from
// (s + a)/2 to (s + b)/2, crosses the other face, which happens when one folds through the other
// around s. Faces sharing an edge never count (a fold across an edge is a face turning over,
// which the flow checks by normals).
bool facesCross(const TriMesh& m, const Face& f, const Face& g) {
  const auto& P = m.positions;
  int i = -1, j = -1;
  const int shared = sharedVertices(f, g, i, j);
  if (shared == 0) {
    // segmentCrossesTriangle for the six edges, each face's plane and each corner's side of the
    // other's plane computed once (the same arithmetic, so the same answers).
    const Vec3 &f0 = P[f[0]], &f1 = P[f[1]], &f2 = P[f[2]], &g0 = P[g[0]], &g1 = P[g[1]], &g2 = P[g[2]];
    const Vec3 nf = (f1 - f0).cross(f2 - f0), ng = (g1 - g0).cross(g2 - g0);
    double sideOfF[3], sideOfG[3];  // f's corners against g's plane, g's against f's
    for (int k = 0; k < 3; ++k) {
      sideOfF[k] = ng.dot(P[f[k]] - g0);
      sideOfG[k] = nf.dot(P[g[k]] - f0);
    }
    for (int k = 0; k < 3; ++k) {
      const int next = (k + 1) % 3;
      if (opposite(sideOfF[k], sideOfF[next]) && segmentPassesInside(P[f[k]], P[f[next]], g0, g1, g2)) return true;
      if (opposite(sideOfG[k], sideOfG[next]) && segmentPassesInside(P[g[k]], P[g[next]], f0, f1, f2)) return true;
    }
    return false;
  }
  if (shared != 1) return false;
  auto halfway = [&](const Face& a, int at, const Face& b) {
    const Vec3& s = P[a[at]];
    return segmentCrossesTriangle(0.5 * (s + P[a[(at + 1) % 3]]), 0.5 * (s + P[a[(at + 2) % 3]]), P[b[0]], P[b[1]],
                                  P[b[2]]);
  };
  return halfway(f, i, g) || halfway(g, j, f);
}

namespace {

// Calls visit(f, g) for each pair of faces (f < g) whose boxes overlap, skipping pairs with
// neither face in `only`; stops when visit returns true. Broad phase: a uniform grid of cells about
// the mean face size, as (cell, face) entries sorted by cell; a pair is tested only in the first
// cell both faces cover, so once.
// With `only`, the grid holds only the faces whose box meets the flagged faces' bounding box (a
// pair needs a flagged face, whose box it overlaps): a step that moved a small region of a large
// scan sorts the region's neighbourhood, not the scan (the sort was 40 % of a region's step).
// A grid with at most kDenseCellsPerFace cells per face it holds, plus kDenseCellsAlways, is
// numbered densely (candidatePairs).
constexpr std::int64_t kDenseCellsPerFace = 16, kDenseCellsAlways = 1 << 16;

template <class Visit>
void candidatePairs(const TriMesh& m, const std::vector<std::uint8_t>* only, Visit visit) {
  const int nf = m.faceCount();
  if (nf < 2) return;
  std::vector<Box> boxes(nf);
  for (int f = 0; f < nf; ++f) boxes[f] = boxOf(m, m.faces[f]);
  std::vector<std::uint8_t> inGrid(nf, 1);
  if (only) {
    Box flagged;  // empty
    for (int f = 0; f < nf; ++f)
      if ((*only)[f]) {
        flagged.lo = flagged.lo.cwiseMin(boxes[f].lo);
        flagged.hi = flagged.hi.cwiseMax(boxes[f].hi);
      }
    for (int f = 0; f < nf; ++f) inGrid[f] = (*only)[f] || boxes[f].meets(flagged);
  }
  Box all;
  double extentSum = 0;
  int gridFaces = 0;
  for (int f = 0; f < nf; ++f) {
    if (!inGrid[f]) continue;
    all.lo = all.lo.cwiseMin(boxes[f].lo);
    all.hi = all.hi.cwiseMax(boxes[f].hi);
    extentSum += (boxes[f].hi - boxes[f].lo).maxCoeff();
    ++gridFaces;
  }
  if (gridFaces < 2) return;
  // Cells of about the mean box size (each face lands in a few cells, each cell holds a few
  // faces), and at most 2^20 cells per axis so that a cell's coordinates pack into one key.
  constexpr double kMaxCellsPerAxis = 1 << 20;
  const double cell = std::max({extentSum / gridFaces, (all.hi - all.lo).maxCoeff() / kMaxCellsPerAxis, 1e-300});
  using Cell = std::array<std::int64_t, 3>;
  auto cellOf = [&](const Vec3& p) {
    Cell c;
    for (int axis = 0; axis < 3; ++axis)
      c[axis] = std::min<std::int64_t>(static_cast<std::int64_t>((p[axis] - all.lo[axis]) / cell), (1 << 21) - 1);
    return c;
  };
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) { return std::uint64_t((i << 42) | (j << 21) | k); };
  // A grid of few enough cells is numbered densely: its entries are bucketed by cell in linear
  // time, and the flagged faces' cells are marked in an array, where a general grid sorts both
  // (the two sorts were a large share of a small region's run, docs/decisions.md, "Regions"). The
  // pairs tested are the same; only their order may differ.
  const Cell top = cellOf(all.hi);
  const std::int64_t ny = top[1] + 1, nz = top[2] + 1;
  const bool dense = static_cast<double>(top[0] + 1) * static_cast<double>(ny) * static_cast<double>(nz) <=
                     static_cast<double>(kDenseCellsPerFace * gridFaces + kDenseCellsAlways);
  const std::int64_t cellCount = dense ? (top[0] + 1) * ny * nz : 0;
  auto denseIndex = [&](std::uint64_t k) {
    constexpr std::uint64_t mask = (1 << 21) - 1;
    return static_cast<std::size_t>((static_cast<std::int64_t>(k >> 42) * ny + static_cast<std::int64_t>((k >> 21) & mask)) * nz +
                                    static_cast<std::int64_t>(k & mask));
  };
  std::vector<std::uint8_t> flaggedMark;
  std::vector<Cell> lo(nf), hi(nf);
  // A face much larger than the mean (a CAD sliver's long side among small faces) would cover too
  // many cells: such faces are tested against every face instead.
  std::vector<std::uint8_t> large(nf, 0);
  std::vector<std::pair<std::uint64_t, int>> entries;
  entries.reserve(static_cast<std::size_t>(nf) * 4);
  // With `only`, the flagged faces' cells first; an unflagged face enters only the cells a flagged
  // face covers (a pair needs a flagged face, and it is tested in a cell both cover): the fixed
  // faces around a moving region (a region's obstacles, the rest of a scan) mostly lie in cells no
  // moving face reaches, and sorting them was a fifth of a 50,000-face region's step. The pairs
  // tested, and their order within a cell, are those of the full grid.
  std::vector<std::uint64_t> flaggedCells;
  for (int pass = only ? 0 : 1; pass < 2; ++pass) {
    for (int f = 0; f < nf; ++f) {
      if (!inGrid[f]) continue;
      if (only && (pass == 0) != ((*only)[f] != 0)) continue;
      lo[f] = cellOf(boxes[f].lo);
      hi[f] = cellOf(boxes[f].hi);
      const std::int64_t cells = (hi[f][0] - lo[f][0] + 1) * (hi[f][1] - lo[f][1] + 1) * (hi[f][2] - lo[f][2] + 1);
      if (cells > kMaxCellsPerFace) {
        large[f] = 1;
        continue;
      }
      const bool filtered = only && pass == 1;
      for (std::int64_t i = lo[f][0]; i <= hi[f][0]; ++i)
        for (std::int64_t j = lo[f][1]; j <= hi[f][1]; ++j)
          for (std::int64_t k = lo[f][2]; k <= hi[f][2]; ++k) {
            const std::uint64_t here = key(i, j, k);
            if (filtered && (dense ? !flaggedMark[denseIndex(here)]
                                   : !std::binary_search(flaggedCells.begin(), flaggedCells.end(), here)))
              continue;
            entries.emplace_back(here, f);
          }
    }
    if (pass == 0 && dense) {
      flaggedMark.assign(static_cast<std::size_t>(cellCount), 0);
      for (const auto& e : entries) flaggedMark[denseIndex(e.first)] = 1;
    } else if (pass == 0) {
      flaggedCells.reserve(entries.size());
      for (const auto& e : entries) flaggedCells.push_back(e.first);
      std::sort(flaggedCells.begin(), flaggedCells.end());
      flaggedCells.erase(std::unique(flaggedCells.begin(), flaggedCells.end()), flaggedCells.end());
    }
  }
  if (dense) {  // a counting sort by cell, stable
    std::vector<std::uint32_t> start(static_cast<std::size_t>(cellCount) + 1, 0);
    for (const auto& e : entries) ++start[denseIndex(e.first) + 1];
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    std::vector<std::pair<std::uint64_t, int>> sorted(entries.size());
    for (const auto& e : entries) sorted[start[denseIndex(e.first)]++] = e;
    entries.swap(sorted);
  } else {
    std::sort(entries.begin(), entries.end());
  }

  auto test = [&](int f, int g) {
    if (only && !(*only)[f] && !(*only)[g]) return false;
    if (!boxes[f].meets(boxes[g])) return false;
    return visit(std::min(f, g), std::max(f, g));
  };
  for (std::size_t a = 0; a < entries.size();) {
    std::size_t b = a;
    while (b < entries.size() && entries[b].first == entries[a].first) ++b;
    const std::uint64_t here = entries[a].first;
    for (std::size_t x = a; x < b; ++x)
      for (std::size_t y = x + 1; y < b; ++y) {
        const int f = entries[x].second, g = entries[y].second;
        // The first cell both cover (the corner of their cell ranges' overlap) tests the pair.
        if (key(std::max(lo[f][0], lo[g][0]), std::max(lo[f][1], lo[g][1]), std::max(lo[f][2], lo[g][2])) != here)
          continue;
        if (test(f, g)) return;
      }
    a = b;
  }
  for (int f = 0; f < nf; ++f) {
    if (!large[f]) continue;
    for (int g = 0; g < nf; ++g)  // large–large pairs once, from the smaller index
      if (g != f && inGrid[g] && !(large[g] && g < f) && test(f, g)) return;
  }
}

}  // namespace

std::vector<int> selfIntersectingFaces(const TriMesh& mesh, const std::vector<std::uint8_t>* onlyFace) {
  return facesOfCrossingPairs(mesh, [&](auto visit) { candidatePairs(mesh, onlyFace, visit); });
}

bool selfIntersects(const TriMesh& mesh, const std::vector<std::uint8_t>* onlyFace) {
  return anyPairCrosses(mesh, [&](auto visit) { candidatePairs(mesh, onlyFace, visit); });
}

bool rewrittenFacesCross(const TriMesh& before, const TriMesh& after, const std::vector<std::uint8_t>& activeFace) {
  if (before.positions != after.positions || before.faces.size() != after.faces.size())
    return selfIntersects(after, &activeFace);
  std::vector<std::uint8_t> rewritten(after.faces.size(), 0);
  bool any = false;
  for (std::size_t f = 0; f < after.faces.size(); ++f) {
    if (after.faces[f] == before.faces[f]) continue;
    if (!activeFace[f]) return selfIntersects(after, &activeFace);
    rewritten[f] = 1, any = true;
  }
  return any && selfIntersects(after, &rewritten);
}

}  // namespace elastica
