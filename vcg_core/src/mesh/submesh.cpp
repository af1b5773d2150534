#include "mesh/submesh.h"

#include <algorithm>
#include <numeric>
#include <unordered_set>

namespace elastica {

VertexFaces vertexFaces(const TriMesh& mesh) {
  // Sized first: growing each list by push_back cost about four allocations per vertex.
  std::vector<int> count(mesh.positions.size(), 0);
  for (const Face& t : mesh.faces)
    for (int v : t) ++count[v];
  VertexFaces vf(mesh.positions.size());
  for (std::size_t v = 0; v < vf.size(); ++v) vf[v].reserve(count[v]);
  for (int f = 0; f < mesh.faceCount(); ++f) {
    for (int v : mesh.faces[f]) vf[v].push_back(f);
  }
  return vf;
}

int fansAt(const TriMesh& mesh, const int* faces, std::size_t count, int v, std::vector<int>& fan,
           std::vector<std::pair<int, int>>& spokes) {
  const int n = static_cast<int>(count);
  // Union-find over the faces in `fan` (parents first, fan numbers last): two faces that hold the
  // same spoke (edge at v) are one fan.
  fan.resize(n);
  std::iota(fan.begin(), fan.end(), 0);
  auto root = [&](int i) {
    while (fan[i] != i) i = fan[i] = fan[fan[i]];
    return i;
  };
  spokes.clear();
  for (int i = 0; i < n; ++i)
    for (int x : mesh.faces[faces[i]])
      if (x != v) spokes.emplace_back(x, i);
  std::sort(spokes.begin(), spokes.end());
  for (std::size_t k = 1; k < spokes.size(); ++k) {
    if (spokes[k].first != spokes[k - 1].first) continue;
    const int a = root(spokes[k].second), b = root(spokes[k - 1].second);
    if (a != b) fan[std::max(a, b)] = std::min(a, b);  // a fan's root is its first face
  }
  for (int i = 0; i < n; ++i) fan[i] = root(i);
  // Numbered in order: a fan's root comes before its members, so it is numbered first (negative
  // while numbering, -1 - number, to tell numbers from roots).
  int fans = 0;
  for (int i = 0; i < n; ++i) fan[i] = fan[i] == i ? -1 - fans++ : fan[fan[i]];
  for (int& x : fan) x = -1 - x;
  return fans;
}

VertexFaceIndex::VertexFaceIndex(const TriMesh& mesh) : offset_(mesh.positions.size() + 1, 0), face_(3 * mesh.faces.size()) {
  for (const Face& t : mesh.faces)
    for (int v : t) ++offset_[v + 1];
  std::partial_sum(offset_.begin(), offset_.end(), offset_.begin());
  // Filled backwards from each vertex's end: no cursor array as large as the mesh.
  for (int f = mesh.faceCount() - 1; f >= 0; --f)
    for (int k = 2; k >= 0; --k) face_[--offset_[mesh.faces[f][k] + 1]] = f;
  // offset_[v + 1] now points at v's first face, i.e. offset_ is shifted by one: put it back.
  offset_.erase(offset_.begin());
  offset_.push_back(static_cast<int>(face_.size()));
}

VertexFaceIndex::Range VertexFaceIndex::operator[](int v) const {
  auto range = [](const std::vector<int>& list) { return Range{list.data(), list.data() + list.size()}; };
  if (v >= baseVertices()) {
    const std::size_t i = static_cast<std::size_t>(v - baseVertices());
    return i < appended_.size() ? range(appended_[i]) : Range{nullptr, nullptr};
  }
  if (!edited_.empty()) {
    const auto at = edited_.find(v);
    if (at != edited_.end()) return range(at->second);
  }
  return {face_.data() + offset_[v], face_.data() + offset_[v + 1]};
}

std::vector<int>& VertexFaceIndex::edit(int v) {
  if (v >= baseVertices()) {
    const std::size_t i = static_cast<std::size_t>(v - baseVertices());
    if (i >= appended_.size()) appended_.resize(i + 1);
    return appended_[i];
  }
  const auto at = edited_.find(v);
  if (at != edited_.end()) return at->second;
  return edited_.emplace(v, (*this)[v].copy()).first->second;
}

std::size_t VertexFaceIndex::byteSize() const {
  std::size_t bytes = (offset_.size() + face_.size()) * sizeof(int) + appended_.capacity() * sizeof(std::vector<int>);
  for (const auto& [v, faces] : edited_) bytes += sizeof(v) + sizeof(faces) + faces.capacity() * sizeof(int);
  for (const auto& faces : appended_) bytes += faces.capacity() * sizeof(int);
  return bytes;
}

namespace {

// The faces within `rings` rings of `seeds`, sorted, and the piece they make.
template <class Mesh, class Adjacency, class FaceAt, class PositionAt>
Submesh extract(const Mesh& mesh, const Adjacency& adjacency, FaceAt faceAt, PositionAt positionAt, const std::vector<int>& seeds,
                int rings) {
  std::unordered_set<int> inVertex(seeds.begin(), seeds.end()), inFace;
  std::vector<int> frontier = seeds, faces;
  for (int r = 0; r < rings; ++r) {
    std::vector<int> next;
    for (int v : frontier) {
      for (int f : adjacency[v]) {
        if (!inFace.insert(f).second) continue;
        faces.push_back(f);
        for (int w : faceAt(mesh, f))
          if (inVertex.insert(w).second) next.push_back(w);
      }
    }
    frontier.swap(next);
  }
  std::sort(faces.begin(), faces.end());

  Submesh sub;
  std::unordered_map<int, int> local;
  local.reserve(2 * faces.size());
  sub.mesh.faces.reserve(faces.size());
  sub.face.reserve(faces.size());
  for (int f : faces) {
    Face t;
    for (int k = 0; k < 3; ++k) {
      const int v = faceAt(mesh, f)[k];
      const auto [at, added] = local.emplace(v, static_cast<int>(sub.vertex.size()));
      if (added) {
        sub.vertex.push_back(v);
        sub.mesh.positions.push_back(positionAt(mesh, v));
      }
      t[k] = at->second;
    }
    sub.mesh.faces.push_back(t);
    sub.face.push_back(f);
  }
  return sub;
}

}  // namespace

Submesh extractSubmesh(const TriMesh& mesh, const VertexFaces& adjacency, const std::vector<int>& seeds, int rings) {
  return extract(
      mesh, adjacency, [](const TriMesh& m, int f) -> const Face& { return m.faces[f]; },
      [](const TriMesh& m, int v) -> const Vec3& { return m.positions[v]; }, seeds, rings);
}

Submesh extractSubmesh(const AppendedMesh& mesh, const VertexFaceIndex& adjacency, const std::vector<int>& seeds, int rings) {
  return extract(
      mesh, adjacency, [](const AppendedMesh& m, int f) -> const Face& { return m.face(f); },
      [](const AppendedMesh& m, int v) -> const Vec3& { return m.position(v); }, seeds, rings);
}

}  // namespace elastica
