// SPDX-License-Identifier: GPL-3.0-or-later
// A piece of a mesh around a region, with the maps back to the whole. Local work (fairing one
// patch of a large scan) then costs in proportion to the patch, not to the model.
#pragma once

#include <elastica/types.h>
#include <elastica/vertex_faces.h>

#include <vector>

namespace elastica {

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

struct Submesh {
  TriMesh mesh;
  std::vector<int> vertex;  ///< local vertex → vertex of the whole mesh
  std::vector<int> face;    ///< local face → face of the whole mesh
};

/// The faces within `rings` face-rings of `seeds` (rings = 1: the faces that use a seed; 2: also
/// the faces that use any vertex of those; …): faces in their original order, vertices in order of
/// first use. Time and memory in proportion to the piece, not to the mesh.
/// `adjacency` holds the faces at each vertex of `mesh` (for an AppendedMesh, with its appended
/// faces added and its rewired ones edited).
Submesh extractSubmesh(const TriMesh& mesh, const VertexFaces& adjacency, const std::vector<int>& seeds, int rings);
Submesh extractSubmesh(const AppendedMesh& mesh, const VertexFaces& adjacency, const std::vector<int>& seeds, int rings);

}  // namespace elastica
