// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/vertex_faces.h>

#include <numeric>

namespace elastica {

std::vector<int> VertexFaces::FaceRange::copy() const {
  std::vector<int> faces;
  faces.reserve(size());
  for (int f : *this) faces.push_back(f);
  return faces;
}

// A counting sort of the corners by vertex. Filled backwards from each vertex's end, so that no
// cursor array as large as the mesh is needed and each vertex's corners come out in increasing
// order.
void VertexFaces::rebuild(int vertexCount, const std::vector<Face>& faces) {
  edited_.clear();
  appended_.clear();
  offset_.assign(static_cast<std::size_t>(vertexCount) + 1, 0);
  corner_.resize(3 * faces.size());
  for (const Face& t : faces)
    for (int v : t) ++offset_[v + 1];
  std::partial_sum(offset_.begin(), offset_.end(), offset_.begin());
  for (int c = static_cast<int>(corner_.size()) - 1; c >= 0; --c) corner_[--offset_[faces[c / 3][c % 3] + 1]] = c;
  // offset_[v + 1] now points at v's first corner, i.e. offset_ is shifted by one: put it back.
  for (int v = 0; v < vertexCount; ++v) offset_[v] = offset_[v + 1];
  offset_[vertexCount] = static_cast<int>(corner_.size());
}

VertexFaces::CornerRange VertexFaces::corners(int v) const {
  auto range = [](const std::vector<int>& list) { return CornerRange{list.data(), list.data() + list.size()}; };
  if (v >= builtVertexCount()) {
    const std::size_t i = static_cast<std::size_t>(v - builtVertexCount());
    return i < appended_.size() ? range(appended_[i]) : CornerRange{nullptr, nullptr};
  }
  if (!edited_.empty()) {
    const auto at = edited_.find(v);
    if (at != edited_.end()) return range(at->second);
  }
  return {corner_.data() + offset_[v], corner_.data() + offset_[v + 1]};
}

std::vector<int>& VertexFaces::edit(int v) {
  if (v >= builtVertexCount()) {
    const std::size_t i = static_cast<std::size_t>(v - builtVertexCount());
    if (i >= appended_.size()) appended_.resize(i + 1);
    return appended_[i];
  }
  const auto at = edited_.find(v);
  if (at != edited_.end()) return at->second;
  const CornerRange built = corners(v);
  return edited_.emplace(v, std::vector<int>(built.begin(), built.end())).first->second;
}

void VertexFaces::addFace(int f, const Face& t) {
  for (int k = 0; k < 3; ++k) edit(t[k]).push_back(3 * f + k);
}

std::size_t VertexFaces::byteSize() const {
  std::size_t bytes = (offset_.size() + corner_.size()) * sizeof(int) + appended_.capacity() * sizeof(std::vector<int>);
  for (const auto& [v, corners] : edited_) bytes += sizeof(v) + sizeof(corners) + corners.capacity() * sizeof(int);
  for (const auto& corners : appended_) bytes += corners.capacity() * sizeof(int);
  return bytes;
}

std::vector<std::vector<int>> faceListsOf(const TriMesh& mesh) {
  const VertexFaces built(mesh.vertexCount(), mesh.faces);
  std::vector<std::vector<int>> lists(mesh.positions.size());
  for (int v = 0; v < mesh.vertexCount(); ++v) lists[v] = built.faces(v).copy();
  return lists;
}

}  // namespace elastica
