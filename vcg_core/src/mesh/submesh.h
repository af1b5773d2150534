// A piece of a mesh around a region, with the maps back to the whole. Local work (fairing one
// patch of a large scan) then costs in proportion to the patch, not to the model.
#pragma once

#include <elastica/types.h>

#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

namespace elastica {

/// For each vertex, the faces that use it (built once, extended as faces are appended).
using VertexFaces = std::vector<std::vector<int>>;
VertexFaces vertexFaces(const TriMesh& mesh);

/// A mesh extended without being copied: the vertices and faces of `base` (whose faces may be
/// rewired in place), then those appended here. Hole filling grows a scan this way, so that a
/// scan of millions of vertices is never held twice.
struct AppendedMesh {
  explicit AppendedMesh(TriMesh& base) : base(&base) {}
  TriMesh* base;
  std::vector<Vec3> positions;  ///< vertices from base->vertexCount() on
  std::vector<Face> faces;      ///< faces from base->faceCount() on

  int baseVertices() const { return base->vertexCount(); }
  int baseFaces() const { return base->faceCount(); }
  int vertexCount() const { return baseVertices() + static_cast<int>(positions.size()); }
  int faceCount() const { return baseFaces() + static_cast<int>(faces.size()); }
  const Vec3& position(int v) const { return v < baseVertices() ? base->positions[v] : positions[v - baseVertices()]; }
  const Face& face(int f) const { return f < baseFaces() ? base->faces[f] : faces[f - baseFaces()]; }
  Face& face(int f) { return f < baseFaces() ? base->faces[f] : faces[f - baseFaces()]; }
};

/// For each vertex of an AppendedMesh, the faces that use it: compact arrays (CSR, 4 bytes per
/// corner and per vertex: a third of the mesh's own bytes, where vertexFaces()' lists take about
/// as much as the mesh) for the base as it was given, and a list of its own for each vertex whose
/// faces have changed since (edit()) and for each vertex appended since.
class VertexFaceIndex {
 public:
  /// `mesh`'s faces must use vertices in [0, vertexCount()).
  explicit VertexFaceIndex(const TriMesh& mesh);

  /// The faces of one vertex, in the order they were listed (the base's in increasing order).
  struct Range {
    const int *first, *last;
    const int* begin() const { return first; }
    const int* end() const { return last; }
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
    bool empty() const { return first == last; }
    int front() const { return *first; }
    std::vector<int> copy() const { return {first, last}; }
  };
  Range operator[](int v) const;
  /// The list of `v` to change (copied out of the compact arrays the first time); `v` may be a
  /// vertex appended after the index was built.
  std::vector<int>& edit(int v);
  std::size_t byteSize() const;

 private:
  int baseVertices() const { return static_cast<int>(offset_.size()) - 1; }
  std::vector<int> offset_, face_;
  std::unordered_map<int, std::vector<int>> edited_;  // base vertices whose faces changed
  std::vector<std::vector<int>> appended_;            // vertices from baseVertices() on
};

/// Groups `faces` (the faces around vertex `v`) into fans, faces joined across an edge at v: sets
/// fan[i] to the fan of faces[i], fans numbered in order of their first face in `faces`, and
/// returns how many there are (more than one: a bow-tie vertex). `spokes` is scratch, reused
/// between calls so that a pass over every vertex allocates nothing per vertex.
int fansAt(const TriMesh& mesh, const int* faces, std::size_t count, int v, std::vector<int>& fan,
           std::vector<std::pair<int, int>>& spokes);

struct Submesh {
  TriMesh mesh;
  std::vector<int> vertex;  ///< local vertex → vertex of the whole mesh
  std::vector<int> face;    ///< local face → face of the whole mesh
};

/// The faces within `rings` face-rings of `seeds` (rings = 1: the faces that use a seed; 2: also
/// the faces that use any vertex of those; …): faces in their original order, vertices in order of
/// first use. Time and memory in proportion to the piece, not to the mesh.
Submesh extractSubmesh(const TriMesh& mesh, const VertexFaces& adjacency, const std::vector<int>& seeds, int rings);
Submesh extractSubmesh(const AppendedMesh& mesh, const VertexFaceIndex& adjacency, const std::vector<int>& seeds, int rings);

}  // namespace elastica
