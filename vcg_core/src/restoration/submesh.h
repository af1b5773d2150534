// A piece of a mesh around a region, with the maps back to the whole. Local work (fairing one
// patch of a large scan) then costs in proportion to the patch, not to the model.
#pragma once

#include <elastica/types.h>

#include <vector>

namespace elastica {

/// For each vertex, the faces that use it (built once, extended as faces are appended).
using VertexFaces = std::vector<std::vector<int>>;
VertexFaces vertexFaces(const TriMesh& mesh);

struct Submesh {
  TriMesh mesh;
  std::vector<int> vertex;  ///< local vertex → vertex of the whole mesh
  std::vector<int> face;    ///< local face → face of the whole mesh
};

/// The faces within `rings` face-rings of `seeds` (rings = 1: the faces that use a seed; 2: also
/// the faces that use any vertex of those; …): faces in their original order, vertices in order of
/// first use.
Submesh extractSubmesh(const TriMesh& mesh, const VertexFaces& adjacency, const std::vector<int>& seeds, int rings);

}  // namespace elastica
