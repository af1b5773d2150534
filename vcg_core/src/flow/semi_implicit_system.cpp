// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/semi_implicit_system.h"

#include <algorithm>
#include <utility>

namespace elastica {
namespace {

// The free vertices around active vertex i (its free neighbours, then i itself if free), in the
// order both the pattern and the values are assembled. `weight` gives C_ij per ring entry.
template <class Weight>
void freeColumn(const Topology& topo, const std::vector<int>& freeIndex, int i, Weight weight,
                std::vector<std::pair<int, double>>& column) {
  column.clear();
  double diagonal = 0;
  for (int k = topo.ringBegin(i); k < topo.ringEnd(i); ++k) {
    const double w = weight(k);
    diagonal -= w;
    const int r = freeIndex[topo.ringVertex(k)];
    if (r >= 0) column.emplace_back(r, w);
  }
  if (freeIndex[i] >= 0) column.emplace_back(freeIndex[i], diagonal);
}

}  // namespace

void SemiImplicitSystem::buildPattern(const Topology& topo, const std::vector<std::uint8_t>& active,
                                      const std::vector<int>& freeIndex, int n) {
  // Column r of free vertex u has a row wherever some active vertex i holds both in its closed
  // ring (i is u or a neighbour of u; the row is i or a neighbour of i, free), and the diagonal.
  // Built column by column, straight into the compressed arrays: through 8 million triplets
  // (Eigen's setFromTriplets), one pattern of the armadillo's 1,978-edge hole cost about a second,
  // and every edge flip of the flow makes a new one. The products' slots are found in the same
  // pass: while column r is being written, a scatter array holds where each of its rows lands, and
  // every active i around u reads the slots of its products (·, r) from it (a binary search per
  // product, after the fact, was half of the pattern's time).
  const int nv = topo.vertexCount();
  std::vector<int> vertexOfRow(n, -1);
  for (int v = 0; v < nv; ++v)
    if (freeIndex[v] >= 0) vertexOfRow[freeIndex[v]] = v;
  // Where each active vertex's m × m products start in slot_ (assembleMatrix's order).
  std::vector<int> productStart(nv + 1, 0);
  for (int i = 0; i < nv; ++i) {
    int m = 0;
    if (active[i]) {
      for (int k = topo.ringBegin(i); k < topo.ringEnd(i); ++k) m += freeIndex[topo.ringVertex(k)] >= 0;
      m += freeIndex[i] >= 0;
    }
    productStart[i + 1] = productStart[i] + m * m;
  }
  slot_.assign(productStart[nv], -1);
  std::vector<int> outer(n + 1, 0), inner, rows, around;
  inner.reserve(static_cast<std::size_t>(n) * 20);
  std::vector<int> where(n, -1);         // row → its slot in the column being written
  std::vector<int> seen(n, -1);          // row → the last column that listed it
  std::vector<int> columnOf;             // the closed free columns of the vertices around u, one after another
  std::vector<int> columnStart;
  for (int c = 0; c < n; ++c) {
    const int u = vertexOfRow[c];
    rows.assign(1, c);
    seen[c] = c;
    around.clear();
    columnOf.clear();
    columnStart.assign(1, 0);
    auto closedRing = [&](int i) {
      if (!active[i]) return;
      freeColumn(topo, freeIndex, i, [](int) { return 0.0; }, column_);
      around.push_back(i);
      for (const auto& entry : column_) {
        columnOf.push_back(entry.first);
        if (seen[entry.first] != c) seen[entry.first] = c, rows.push_back(entry.first);
      }
      columnStart.push_back(static_cast<int>(columnOf.size()));
    };
    closedRing(u);
    for (int k = topo.ringBegin(u); k < topo.ringEnd(u); ++k) closedRing(topo.ringVertex(k));
    std::sort(rows.begin(), rows.end());
    const int first = static_cast<int>(inner.size());
    for (std::size_t j = 0; j < rows.size(); ++j) where[rows[j]] = first + static_cast<int>(j);
    inner.insert(inner.end(), rows.begin(), rows.end());
    outer[c + 1] = static_cast<int>(inner.size());
    // Products (a, b) of vertex i with b = this column: slot_[start + a·m + b] (i's free column
    // lists u once, at position b).
    for (std::size_t t = 0; t < around.size(); ++t) {
      const int* col = columnOf.data() + columnStart[t];
      const int m = columnStart[t + 1] - columnStart[t];
      int b = 0;
      while (col[b] != c) ++b;
      int* out = slot_.data() + productStart[around[t]] + b;
      for (int a = 0; a < m; ++a) out[a * m] = where[col[a]];
    }
  }
  K_.resize(n, n);
  K_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), K_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), K_.innerIndexPtr());
  std::fill(K_.valuePtr(), K_.valuePtr() + inner.size(), 0.0);
  diagonalSlot_.resize(n);
  for (int r = 0; r < n; ++r) {
    const int* begin = K_.innerIndexPtr() + K_.outerIndexPtr()[r];
    const int* end = K_.innerIndexPtr() + K_.outerIndexPtr()[r + 1];
    diagonalSlot_[r] = static_cast<int>(std::lower_bound(begin, end, r) - K_.innerIndexPtr());
  }
  rhs_.resize(n);
  patterned_ = true;
}

void SemiImplicitSystem::assemble(const Topology& topo, const Geometry& geo, const std::vector<std::uint8_t>& active,
                                  const std::vector<int>& freeIndex, int n, const std::vector<double>& speed, double tau) {
  assembleMatrix(topo, geo.edgeWeight, geo.vertexArea, active, freeIndex, n, 1.0, 0.5 * tau);
  for (int v = 0; v < topo.vertexCount(); ++v) {
    const int r = freeIndex[v];
    if (r >= 0) rhs_[r] = tau * geo.vertexArea[v] * speed[v];
  }
}

void SemiImplicitSystem::assembleMatrix(const Topology& topo, const std::vector<double>& edgeWeight,
                                        const std::vector<double>& vertexArea, const std::vector<std::uint8_t>& active,
                                        const std::vector<int>& freeIndex, int n, double mass, double scale) {
  if (!patterned_ || K_.rows() != n) buildPattern(topo, active, freeIndex, n);
  double* value = K_.valuePtr();
  std::fill(value, value + K_.nonZeros(), 0.0);
  std::size_t next = 0;  // the pattern's products, in the same order
  for (int i = 0; i < topo.vertexCount(); ++i) {
    if (!active[i]) continue;
    freeColumn(topo, freeIndex, i, [&](int k) { return edgeWeight[topo.ringEdge(k)]; }, column_);
    const std::size_t m = column_.size();
    if (vertexArea[i] > 0) {  // a vertex without area contributes nothing (its slots stay zero)
      const double s = scale / vertexArea[i];
      for (std::size_t a = 0; a < m; ++a)
        for (std::size_t b = 0; b < m; ++b) value[slot_[next + a * m + b]] += s * column_[a].second * column_[b].second;
    }
    next += m * m;
  }
  if (mass == 0) return;
  for (int v = 0; v < topo.vertexCount(); ++v) {
    const int r = freeIndex[v];
    if (r >= 0) value[diagonalSlot_[r]] += mass * vertexArea[v];
  }
}

void SemiImplicitSystem::addEdgeLaplacian(const Topology& topo, const std::vector<double>& edgeWeight,
                                          const std::vector<int>& freeIndex, double scale) {
  edgeSlot_.resize(topo.edgeCount(), {-1, -1});
  double* const value = K_.valuePtr();  // read only while K_ stays compressed
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const double w = scale * edgeWeight[e];
    if (w == 0) continue;
    const auto& ev = topo.edgeVertices(e);
    const int a = freeIndex[ev[0]], b = freeIndex[ev[1]];
    if (!K_.isCompressed()) {  // an entry outside the pattern was inserted: coeffRef throughout
      if (a >= 0) K_.coeffRef(a, a) += w;
      if (b >= 0) K_.coeffRef(b, b) += w;
      if (a >= 0 && b >= 0) K_.coeffRef(a, b) -= w, K_.coeffRef(b, a) -= w;
      continue;
    }
    if (a >= 0) value[diagonalSlot_[a]] += w;
    if (b >= 0) value[diagonalSlot_[b]] += w;
    if (a >= 0 && b >= 0) {
      std::array<int, 2>& slot = edgeSlot_[e];
      if (!holds(slot[0], b, a)) slot[0] = find(b, a);
      if (!holds(slot[1], a, b)) slot[1] = find(a, b);
      if (slot[0] < 0 || slot[1] < 0) {  // not in the pattern: inserted, as coeffRef does
        K_.coeffRef(a, b) -= w;
        K_.coeffRef(b, a) -= w;
        slot = {-1, -1};
        continue;
      }
      value[slot[0]] -= w;
      value[slot[1]] -= w;
    }
  }
}

// Whether value slot `slot` is entry (row, column) of K_ (a slot kept from an earlier call).
bool SemiImplicitSystem::holds(int slot, int row, int column) const {
  return slot >= K_.outerIndexPtr()[column] && slot < K_.outerIndexPtr()[column + 1] && K_.innerIndexPtr()[slot] == row;
}

// The slot of entry (row, column), or −1 if the pattern lacks it.
int SemiImplicitSystem::find(int row, int column) const {
  const int* begin = K_.innerIndexPtr() + K_.outerIndexPtr()[column];
  const int* end = K_.innerIndexPtr() + K_.outerIndexPtr()[column + 1];
  const int* at = std::lower_bound(begin, end, row);
  return at != end && *at == row ? static_cast<int>(at - K_.innerIndexPtr()) : -1;
}

}  // namespace elastica
