// SPDX-License-Identifier: GPL-3.0-or-later
// The faces at each vertex, as corners (corner c = 3·f + k is vertex faces[f][k] of face f), in
// compact arrays (CSR: 4 bytes per corner and per vertex). The one vertex→face adjacency of the
// core: Topology holds one, the file checks build one over the mesh as read, and hole filling
// appends its patches to one without rebuilding it. (Remeshing a patch removes faces as it goes and
// keeps one list per vertex, faceListsOf(): mesh/patch_remeshing.cpp, restoration/patch_angles.cpp.)
//
// Public because Topology (public) holds one and the file checks (elastica_io, on the public API
// only) use it; it is in the operators tier, the lowest that needs it.
#pragma once

#include <elastica/types.h>

#include <cstddef>
#include <unordered_map>
#include <vector>

namespace elastica {

class VertexFaces {
 public:
  /// A vertex's corners (or, through FaceRange, its faces): a range of ints.
  struct CornerRange {
    const int *first, *last;
    const int* begin() const { return first; }
    const int* end() const { return last; }
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
    bool empty() const { return first == last; }
  };
  /// The faces of a vertex's corners (corner / 3), in the corners' order.
  struct FaceRange {
    struct Iterator {
      const int* c;
      int operator*() const { return *c / 3; }
      Iterator& operator++() {
        ++c;
        return *this;
      }
      bool operator!=(const Iterator& o) const { return c != o.c; }
    };
    CornerRange corners;
    Iterator begin() const { return {corners.first}; }
    Iterator end() const { return {corners.last}; }
    std::size_t size() const { return corners.size(); }
    bool empty() const { return corners.empty(); }
    int front() const { return *corners.first / 3; }
    std::vector<int> copy() const;
  };

  VertexFaces() = default;
  /// The corners of `faces` over `vertexCount` vertices, each vertex's in increasing order.
  /// Precondition: every index is in [0, vertexCount) (Topology and the file checks test it first).
  VertexFaces(int vertexCount, const std::vector<Face>& faces) { rebuild(vertexCount, faces); }
  /// As the constructor, reusing this object's storage; forgets every edit.
  void rebuild(int vertexCount, const std::vector<Face>& faces);

  /// Vertices as built (appended ones, see edit(), are not counted).
  int builtVertexCount() const { return static_cast<int>(offset_.size()) - 1; }

  /// The compact arrays as built, for hot loops over a mesh that is never edited (Topology):
  /// the corners of v are corner(k) for k in [offset(v), offset(v + 1)).
  int offset(int v) const { return offset_[v]; }
  int corner(int k) const { return corner_[k]; }

  /// The corners of v, edited or not; v may be a vertex appended since the build (none yet: empty).
  CornerRange corners(int v) const;
  FaceRange faces(int v) const { return {corners(v)}; }

  /// The corner list of `v` to change (copied out of the compact arrays the first time); `v` may
  /// be a vertex appended after the build. Later reads of v see the list.
  std::vector<int>& edit(int v);
  /// Appends face f = `t` to the lists of its three vertices (corner 3f + k to vertex t[k]).
  void addFace(int f, const Face& t);

  std::size_t byteSize() const;

 private:
  std::vector<int> offset_{0}, corner_;
  std::unordered_map<int, std::vector<int>> edited_;  // built vertices whose corners changed
  std::vector<std::vector<int>> appended_;            // vertices from builtVertexCount() on
};

/// The faces at each vertex of `mesh` in increasing order, one growable list per vertex: for the
/// patch editors (remeshing, the border-angle flips and splits), which remove and add faces at most
/// of a patch's vertices, where VertexFaces' edits (a hash map of the changed vertices, read at
/// each look-up) would cost more than they save. Built from a VertexFaces.
std::vector<std::vector<int>> faceListsOf(const TriMesh& mesh);

/// The corner of face `t` (number f) at vertex v: 3f + k where t[k] == v. Precondition: t holds v.
inline int cornerAt(int f, const Face& t, int v) { return 3 * f + (t[0] == v ? 0 : t[1] == v ? 1 : 2); }

}  // namespace elastica
