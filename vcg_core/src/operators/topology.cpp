// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/topology.h>
#include <elastica/vertex_fans.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <string>

namespace elastica {
namespace {

// A half-edge seen from its smaller endpoint, packed in one integer: the larger endpoint << 32 |
// the corner opposite the edge in its face. (A struct of the two, built field by field and copied
// whole, stalled on each copy: the processor cannot forward two small stores into one wide load.)
using Spoke = std::uint64_t;
Spoke spoke(int hi, int corner) { return std::uint64_t(hi) << 32 | std::uint32_t(corner); }
int spokeHi(Spoke s) { return static_cast<int>(s >> 32); }
int spokeCorner(Spoke s) { return static_cast<int>(s & 0xffffffffu); }

// Sorted by (larger endpoint, corner): a vertex's spokes come in increasing corner order, so this
// is the stable order by larger endpoint. A vertex has about six spokes, where an insertion sort
// beats any general-purpose sort; past the limit (a vertex of very high valence) std::sort.
constexpr std::size_t kInsertionSortLimit = 32;

void sortSpokes(std::vector<Spoke>& spokes) {
  if (spokes.size() > kInsertionSortLimit) {
    std::sort(spokes.begin(), spokes.end());
    return;
  }
  for (std::size_t i = 1; i < spokes.size(); ++i) {
    const Spoke s = spokes[i];
    std::size_t j = i;
    for (; j > 0 && spokes[j - 1] > s; --j) spokes[j] = spokes[j - 1];
    spokes[j] = s;
  }
}

}  // namespace

namespace {
std::atomic<int> largestTopology{0};
}  // namespace

int Topology::largestBuilt() { return largestTopology.load(); }
void Topology::resetLargestBuilt() { largestTopology.store(0); }

// Linear in the mesh size apart from sorting each vertex's handful of spokes: the corner lists
// are a counting sort, the edges come vertex by vertex from them, and the one-rings are a counting
// sort of the edges. It runs at every connectivity change (each edge-flip pass, each hole patch,
// remeshing), so it also avoids temporaries as large as the mesh: on a virtual machine their page
// faults cost more than the work.
Topology::Topology(int vertexCount, const std::vector<Face>& faces) { rebuild(vertexCount, faces); }

void Topology::rebuild(int vertexCount, const std::vector<Face>& faces) {
  try {
    build(vertexCount, faces);
  } catch (...) {
    *this = Topology();
    throw;
  }
}

void Topology::build(int vertexCount, const std::vector<Face>& faces) {
  if (vertexCount < 0) throw InvalidInputError("Topology: negative vertex count");
  nv_ = vertexCount;
  faces_ = faces;
  edgeVertices_.clear();
  edgeCorners_.clear();
  boundaryEdges_ = inconsistentEdges_ = 0;
  for (int seen = largestTopology.load(); seen < vertexCount && !largestTopology.compare_exchange_weak(seen, vertexCount);) {
  }
  const int nf = static_cast<int>(faces.size());
  for (int f = 0; f < nf; ++f) {
    const Face& t = faces[f];
    for (int k = 0; k < 3; ++k) {
      if (t[k] < 0 || t[k] >= nv_) {
        throw InvalidInputError("Topology: face " + std::to_string(f) + " references vertex " +
                                std::to_string(t[k]) + ", outside [0, " + std::to_string(nv_) + ")");
      }
    }
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      throw InvalidInputError("Topology: face " + std::to_string(f) + " repeats vertex " +
                              std::to_string(t[0] == t[1] || t[0] == t[2] ? t[0] : t[1]));
    }
  }
  const int nc = 3 * nf;

  // Corners of each vertex in increasing corner number.
  corners_.rebuild(nv_, faces);

  // Undirected edges numbered in (lo, hi) order: for each vertex lo, its spokes to larger
  // neighbours grouped by neighbour. The spokes come in face order and sort stably, so the two
  // corners of an edge are in increasing order. ringOffset_ counts each vertex's edges first.
  // A closed mesh has exactly nc/2 edges; the reserve leaves room for a boundary.
  edgeVertices_.reserve(nc / 2 + nc / 32 + 3);
  edgeCorners_.reserve(nc / 2 + nc / 32 + 3);
  ringOffset_.assign(nv_ + 1, 0);
  boundaryVertex_.assign(nv_, 0);
  std::vector<Spoke> spokes;
  for (int lo = 0; lo < nv_; ++lo) {
    spokes.clear();
    for (int i = cornerBegin(lo); i < cornerEnd(lo); ++i) {
      // The faces around a vertex lie anywhere in the face array: each is asked for from the
      // cache kAhead corners before it is read, so the misses overlap.
      constexpr int kAhead = 16;
      if (i + kAhead < nc) __builtin_prefetch(&faces[corner(i + kAhead) / 3]);
      const int c = corner(i), f = c / 3, k = c % 3;
      // The edge to the next vertex of the face is opposite the previous corner, and vice versa.
      const int next = faces[f][(k + 1) % 3], prev = faces[f][(k + 2) % 3];
      if (next > lo) spokes.push_back(spoke(next, 3 * f + (k + 2) % 3));
      if (prev > lo) spokes.push_back(spoke(prev, 3 * f + (k + 1) % 3));
    }
    sortSpokes(spokes);
    for (std::size_t i = 0; i < spokes.size();) {
      const int hi = spokeHi(spokes[i]);
      std::size_t j = i + 1;
      while (j < spokes.size() && spokeHi(spokes[j]) == hi) ++j;
      if (j - i > 2) {
        throw InvalidInputError("Topology: non-manifold edge between vertices " + std::to_string(lo) + " and " +
                                std::to_string(hi) + " (shared by " + std::to_string(j - i) + " faces)");
      }
      // Element by element (not push_back({a, b}), which went through the stack, see Spoke).
      edgeVertices_.emplace_back();
      edgeVertices_.back()[0] = lo;
      edgeVertices_.back()[1] = hi;
      edgeCorners_.emplace_back();
      if (j - i == 2) {
        const int c0 = spokeCorner(spokes[i]), c1 = spokeCorner(spokes[i + 1]);
        edgeCorners_.back()[0] = c0;
        edgeCorners_.back()[1] = c1;
        if (isInconsistentEdge(edgeCount() - 1)) ++inconsistentEdges_;
      } else {
        edgeCorners_.back()[0] = spokeCorner(spokes[i]);
        edgeCorners_.back()[1] = -1;
        ++boundaryEdges_;
        boundaryVertex_[lo] = boundaryVertex_[hi] = 1;
      }
      ++ringOffset_[lo + 1];
      ++ringOffset_[hi + 1];
      i = j;
    }
  }

  // One-rings: each vertex's edges in increasing edge number (a stable counting sort). That
  // puts the neighbours in increasing order: first those below v (edges numbered by them), then
  // those above.
  std::partial_sum(ringOffset_.begin(), ringOffset_.end(), ringOffset_.begin());
  ringEdge_.resize(ringOffset_[nv_]);
  ringVertex_.resize(ringOffset_[nv_]);
  std::vector<int> cursor(ringOffset_.begin(), ringOffset_.end() - 1);
  for (int e = 0; e < edgeCount(); ++e) {
    const int a = edgeVertices_[e][0], b = edgeVertices_[e][1];
    ringEdge_[cursor[a]] = e;
    ringVertex_[cursor[a]++] = b;
    ringEdge_[cursor[b]] = e;
    ringVertex_[cursor[b]++] = a;
  }
}

int Topology::nonManifoldVertexCount(const std::vector<std::uint8_t>* only) const {
  int count = 0;
  std::vector<int> fan;
  FanScratch scratch;
  for (int v = 0; v < nv_; ++v) {
    if (only && !(*only)[v]) continue;
    const VertexFaces::CornerRange corners = corners_.corners(v);
    if (corners.size() >= 2 && fansAt(faces_, corners.begin(), corners.size(), fan, scratch) > 1) ++count;
  }
  return count;
}

bool Topology::isInconsistentEdge(int e) const {
  const int c0 = edgeCorners_[e][0], c1 = edgeCorners_[e][1], lo = edgeVertices_[e][0];
  if (c1 < 0) return false;
  // Each face traverses the edge from the vertex after the opposite corner.
  return (faces_[c0 / 3][(c0 % 3 + 1) % 3] == lo) == (faces_[c1 / 3][(c1 % 3 + 1) % 3] == lo);
}

std::size_t Topology::byteSize() const {
  auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  return bytes(faces_) + bytes(edgeVertices_) + bytes(edgeCorners_) + bytes(ringOffset_) + bytes(ringVertex_) +
         bytes(ringEdge_) + corners_.byteSize() + bytes(boundaryVertex_);
}

}  // namespace elastica
