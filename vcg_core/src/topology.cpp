#include <elastica/errors.h>
#include <elastica/topology.h>

#include <algorithm>
#include <numeric>
#include <string>

namespace elastica {
namespace {

struct HalfEdge {
  int lo, hi;    // endpoints, lo < hi
  int corner;    // the corner opposite this edge in its face
  bool forward;  // the face traverses the edge lo → hi
};

// Counting sort of (key, value) pairs into CSR arrays.
void buildCsr(int n, const std::vector<std::pair<int, int>>& pairs, std::vector<int>& offset,
              std::vector<int>& value) {
  offset.assign(n + 1, 0);
  for (const auto& p : pairs) ++offset[p.first + 1];
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  value.resize(pairs.size());
  std::vector<int> cursor(offset.begin(), offset.end() - 1);
  for (const auto& p : pairs) value[cursor[p.first]++] = p.second;
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

Topology::Topology(int vertexCount, const std::vector<Face>& faces) : nv_(vertexCount), faces_(faces) {
  if (vertexCount < 0) throw InvalidInputError("Topology: negative vertex count");
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

  // Undirected edges from sorted half-edges.
  std::vector<HalfEdge> half;
  half.reserve(3 * faces.size());
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = faces[f][(k + 1) % 3], b = faces[f][(k + 2) % 3];
      half.push_back({std::min(a, b), std::max(a, b), 3 * f + k, a < b});
    }
  }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.lo != y.lo ? x.lo < y.lo : (x.hi != y.hi ? x.hi < y.hi : x.corner < y.corner);
  });
  for (size_t i = 0; i < half.size();) {
    size_t j = i + 1;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
    if (j - i > 2) {
      throw InvalidInputError("Topology: non-manifold edge between vertices " + std::to_string(half[i].lo) +
                              " and " + std::to_string(half[i].hi) + " (shared by " +
                              std::to_string(j - i) + " faces)");
    }
    edgeVertices_.push_back({half[i].lo, half[i].hi});
    if (j - i == 2) {
      edgeCorners_.push_back({half[i].corner, half[i + 1].corner});
      if (half[i].forward == half[i + 1].forward) ++inconsistentEdges_;
    } else {
      edgeCorners_.push_back({half[i].corner, -1});
      ++boundaryEdges_;
    }
    i = j;
  }

  // One-rings and corner lists.
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(2 * edgeVertices_.size());
  for (int e = 0; e < edgeCount(); ++e) {
    pairs.emplace_back(edgeVertices_[e][0], e);
    pairs.emplace_back(edgeVertices_[e][1], e);
  }
  buildCsr(nv_, pairs, ringOffset_, ringEdge_);
  ringVertex_.resize(ringEdge_.size());
  for (int v = 0; v < nv_; ++v) {
    for (int k = ringOffset_[v]; k < ringOffset_[v + 1]; ++k) {
      const auto& ev = edgeVertices_[ringEdge_[k]];
      ringVertex_[k] = ev[0] == v ? ev[1] : ev[0];
    }
  }
  pairs.clear();
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) pairs.emplace_back(faces[f][k], 3 * f + k);
  buildCsr(nv_, pairs, cornerOffset_, vertexCorner_);

  boundaryVertex_.assign(nv_, 0);
  for (int e = 0; e < edgeCount(); ++e) {
    if (isBoundaryEdge(e)) boundaryVertex_[edgeVertices_[e][0]] = boundaryVertex_[edgeVertices_[e][1]] = 1;
  }

  // Fans around each vertex: faces sharing an edge at the vertex are joined; more than one
  // component means a bow-tie (non-manifold) vertex.
  std::vector<std::pair<int, int>> spokes;  // (neighbour, local face index)
  std::vector<int> parent;
  for (int v = 0; v < nv_; ++v) {
    const int n = cornerEnd(v) - cornerBegin(v);
    if (n < 2) continue;
    spokes.clear();
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), 0);
    for (int i = 0; i < n; ++i) {
      const int c = vertexCorner_[cornerBegin(v) + i];
      const Face& t = faces[c / 3];
      spokes.emplace_back(t[(c % 3 + 1) % 3], i);
      spokes.emplace_back(t[(c % 3 + 2) % 3], i);
    }
    std::sort(spokes.begin(), spokes.end());
    for (size_t i = 1; i < spokes.size(); ++i) {
      if (spokes[i].first == spokes[i - 1].first)
        parent[findRoot(parent, spokes[i].second)] = findRoot(parent, spokes[i - 1].second);
    }
    int components = 0;
    for (int i = 0; i < n; ++i) components += findRoot(parent, i) == i;
    if (components > 1) ++nonManifoldVertices_;
  }
}

std::size_t Topology::byteSize() const {
  auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  return bytes(faces_) + bytes(edgeVertices_) + bytes(edgeCorners_) + bytes(ringOffset_) + bytes(ringVertex_) +
         bytes(ringEdge_) + bytes(cornerOffset_) + bytes(vertexCorner_) + bytes(boundaryVertex_);
}

}  // namespace elastica
