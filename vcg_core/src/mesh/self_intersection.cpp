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

// A grid with at most kDenseCellsPerFace cells per face it holds, plus kDenseCellsAlways, is
// numbered densely (makeGrid).
constexpr std::int64_t kDenseCellsPerFace = 16, kDenseCellsAlways = 1 << 16;

using Cell = std::array<std::int64_t, 3>;
using Entry = std::pair<std::uint64_t, int>;  // (cell key, face)

// A cell's three coordinates (each below 2^21) packed into one key.
std::uint64_t cellKey(std::int64_t i, std::int64_t j, std::int64_t k) { return std::uint64_t((i << 42) | (j << 21) | k); }

// The uniform grid over the boxes of the faces it holds.
struct CellGrid {
  Vec3 lo;
  double size = 0;  // a cell's edge
  std::int64_t ny = 0, nz = 0, cellCount = 0;  // cellCount: dense grids only
  bool dense = false;
  Cell cellOf(const Vec3& p) const {
    Cell c;
    for (int axis = 0; axis < 3; ++axis)
      c[axis] = std::min<std::int64_t>(static_cast<std::int64_t>((p[axis] - lo[axis]) / size), (1 << 21) - 1);
    return c;
  }
  std::size_t denseIndex(std::uint64_t k) const {
    constexpr std::uint64_t mask = (1 << 21) - 1;
    return static_cast<std::size_t>((static_cast<std::int64_t>(k >> 42) * ny + static_cast<std::int64_t>((k >> 21) & mask)) * nz +
                                    static_cast<std::int64_t>(k & mask));
  }
};

// The faces the grid holds: all, or with `only` those whose box meets the flagged faces' bounding box.
std::vector<std::uint8_t> facesInGrid(const std::vector<Box>& boxes, const std::vector<std::uint8_t>* only) {
  const std::size_t nf = boxes.size();
  std::vector<std::uint8_t> inGrid(nf, 1);
  if (!only) return inGrid;
  Box flagged;  // empty
  for (std::size_t f = 0; f < nf; ++f)
    if ((*only)[f]) {
      flagged.lo = flagged.lo.cwiseMin(boxes[f].lo);
      flagged.hi = flagged.hi.cwiseMax(boxes[f].hi);
    }
  for (std::size_t f = 0; f < nf; ++f) inGrid[f] = (*only)[f] || boxes[f].meets(flagged);
  return inGrid;
}

// The grid for the faces in it; false if it holds fewer than two (no pair to test).
bool makeGrid(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& inGrid, CellGrid& grid) {
  Box all;
  double extentSum = 0;
  int gridFaces = 0;
  for (std::size_t f = 0; f < boxes.size(); ++f) {
    if (!inGrid[f]) continue;
    all.lo = all.lo.cwiseMin(boxes[f].lo);
    all.hi = all.hi.cwiseMax(boxes[f].hi);
    extentSum += (boxes[f].hi - boxes[f].lo).maxCoeff();
    ++gridFaces;
  }
  if (gridFaces < 2) return false;
  // Cells of about the mean box size (each face lands in a few cells, each cell holds a few
  // faces), and at most 2^20 cells per axis so that a cell's coordinates pack into one key.
  constexpr double kMaxCellsPerAxis = 1 << 20;
  grid.lo = all.lo;
  grid.size = std::max({extentSum / gridFaces, (all.hi - all.lo).maxCoeff() / kMaxCellsPerAxis, 1e-300});
  // A grid of few enough cells is numbered densely: its entries are bucketed by cell in linear
  // time, and the flagged faces' cells are marked in an array, where a general grid sorts both
  // (the two sorts were a large share of a small region's run, docs/decisions.md, "Regions"). The
  // pairs tested are the same; only their order may differ.
  const Cell top = grid.cellOf(all.hi);
  grid.ny = top[1] + 1, grid.nz = top[2] + 1;
  grid.dense = static_cast<double>(top[0] + 1) * static_cast<double>(grid.ny) * static_cast<double>(grid.nz) <=
               static_cast<double>(kDenseCellsPerFace * gridFaces + kDenseCellsAlways);
  grid.cellCount = grid.dense ? (top[0] + 1) * grid.ny * grid.nz : 0;
  return true;
}

// The broad phase's faces in their cells: each face's cell range, the faces too large for the
// grid, and the (cell, face) entries.
struct GridEntries {
  std::vector<Cell> lo, hi;
  std::vector<std::uint8_t> large;
  std::vector<Entry> entries;
};

// The cells a flagged face covers, for the unflagged faces' pass: marked (dense grid) or sorted.
struct FlaggedCells {
  std::vector<std::uint8_t> mark;
  std::vector<std::uint64_t> sorted;
  void note(const std::vector<Entry>& entries, const CellGrid& grid) {
    if (grid.dense) {
      mark.assign(static_cast<std::size_t>(grid.cellCount), 0);
      for (const auto& e : entries) mark[grid.denseIndex(e.first)] = 1;
      return;
    }
    sorted.reserve(entries.size());
    for (const auto& e : entries) sorted.push_back(e.first);
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  }
  bool has(std::uint64_t cell, const CellGrid& grid) const {
    return grid.dense ? mark[grid.denseIndex(cell)] != 0 : std::binary_search(sorted.begin(), sorted.end(), cell);
  }
};

// Enters face f in the cells its box covers (with `flagged`, only those a flagged face covers),
// or marks it large. A face much larger than the mean (a CAD sliver's long side among small
// faces) would cover too many cells: such faces are tested against every face instead.
void enterFace(int f, const Box& box, const CellGrid& grid, const FlaggedCells* flagged, GridEntries& g) {
  g.lo[f] = grid.cellOf(box.lo);
  g.hi[f] = grid.cellOf(box.hi);
  const Cell &lo = g.lo[f], &hi = g.hi[f];
  const std::int64_t cells = (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
  if (cells > kMaxCellsPerFace) {
    g.large[f] = 1;
    return;
  }
  for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
    for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
      for (std::int64_t k = lo[2]; k <= hi[2]; ++k) {
        const std::uint64_t here = cellKey(i, j, k);
        if (flagged && !flagged->has(here, grid)) continue;
        g.entries.emplace_back(here, f);
      }
}

// The entries of the faces in the grid, sorted by cell.
// With `only`, the flagged faces' cells first; an unflagged face enters only the cells a flagged
// face covers (a pair needs a flagged face, and it is tested in a cell both cover): the fixed
// faces around a moving region (a region's obstacles, the rest of a scan) mostly lie in cells no
// moving face reaches, and sorting them was a fifth of a 50,000-face region's step. The pairs
// tested, and their order within a cell, are those of the full grid.
void enterFaces(const std::vector<Box>& boxes, const std::vector<std::uint8_t>& inGrid, const std::vector<std::uint8_t>* only,
                const CellGrid& grid, GridEntries& g) {
  const int nf = static_cast<int>(boxes.size());
  g.entries.reserve(static_cast<std::size_t>(nf) * 4);
  FlaggedCells flagged;
  for (int pass = only ? 0 : 1; pass < 2; ++pass) {
    for (int f = 0; f < nf; ++f) {
      if (!inGrid[f]) continue;
      if (only && (pass == 0) != ((*only)[f] != 0)) continue;
      enterFace(f, boxes[f], grid, only && pass == 1 ? &flagged : nullptr, g);
    }
    if (pass == 0) flagged.note(g.entries, grid);
  }
  if (grid.dense) {  // a counting sort by cell, stable
    std::vector<std::uint32_t> start(static_cast<std::size_t>(grid.cellCount) + 1, 0);
    for (const auto& e : g.entries) ++start[grid.denseIndex(e.first) + 1];
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    std::vector<Entry> sorted(g.entries.size());
    for (const auto& e : g.entries) sorted[start[grid.denseIndex(e.first)]++] = e;
    g.entries.swap(sorted);
  } else {
    std::sort(g.entries.begin(), g.entries.end());
  }
}

// Calls test(f, g) for the pairs of faces that share a cell, each pair in the first cell both
// cover (the corner of their cell ranges' overlap), so once; true if a test said stop.
template <class Test>
bool testCellPairs(const GridEntries& g, Test test) {
  const std::vector<Entry>& entries = g.entries;
  for (std::size_t a = 0; a < entries.size();) {
    std::size_t b = a;
    while (b < entries.size() && entries[b].first == entries[a].first) ++b;
    const std::uint64_t here = entries[a].first;
    for (std::size_t x = a; x < b; ++x)
      for (std::size_t y = x + 1; y < b; ++y) {
        const int f = entries[x].second, h = entries[y].second;
        const Cell &lf = g.lo[f], &lh = g.lo[h];
        if (cellKey(std::max(lf[0], lh[0]), std::max(lf[1], lh[1]), std::max(lf[2], lh[2])) != here) continue;
        if (test(f, h)) return true;
      }
    a = b;
  }
  return false;
}

// Calls visit(f, g) for each pair of faces (f < g) whose boxes overlap, skipping pairs with
// neither face in `only`; stops when visit returns true. Broad phase: a uniform grid of cells about
// the mean face size, as (cell, face) entries sorted by cell; a pair is tested only in the first
// cell both faces cover, so once.
// With `only`, the grid holds only the faces whose box meets the flagged faces' bounding box (a
// pair needs a flagged face, whose box it overlaps): a step that moved a small region of a large
// scan sorts the region's neighbourhood, not the scan (the sort was 40 % of a region's step).
template <class Visit>
void candidatePairs(const TriMesh& m, const std::vector<std::uint8_t>* only, Visit visit) {
  const int nf = m.faceCount();
  if (nf < 2) return;
  std::vector<Box> boxes(nf);
  for (int f = 0; f < nf; ++f) boxes[f] = boxOf(m, m.faces[f]);
  const std::vector<std::uint8_t> inGrid = facesInGrid(boxes, only);
  CellGrid grid;
  if (!makeGrid(boxes, inGrid, grid)) return;
  GridEntries g{std::vector<Cell>(nf), std::vector<Cell>(nf), std::vector<std::uint8_t>(nf, 0), {}};
  enterFaces(boxes, inGrid, only, grid, g);
  auto test = [&](int f, int h) {
    if (only && !(*only)[f] && !(*only)[h]) return false;
    if (!boxes[f].meets(boxes[h])) return false;
    return visit(std::min(f, h), std::max(f, h));
  };
  if (testCellPairs(g, test)) return;
  for (int f = 0; f < nf; ++f) {
    if (!g.large[f]) continue;
    for (int h = 0; h < nf; ++h)  // large–large pairs once, from the smaller index
      if (h != f && inGrid[h] && !(g.large[h] && h < f) && test(f, h)) return;
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
