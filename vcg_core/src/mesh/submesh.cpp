// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/submesh.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace elastica {

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
      for (int f : adjacency.faces(v)) {
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

Submesh extractSubmesh(const AppendedMesh& mesh, const VertexFaces& adjacency, const std::vector<int>& seeds, int rings) {
  return extract(
      mesh, adjacency, [](const AppendedMesh& m, int f) -> const Face& { return m.face(f); },
      [](const AppendedMesh& m, int v) -> const Vec3& { return m.position(v); }, seeds, rings);
}

}  // namespace elastica
