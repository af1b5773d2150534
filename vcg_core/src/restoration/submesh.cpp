#include "restoration/submesh.h"

#include <algorithm>

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

Submesh extractSubmesh(const TriMesh& mesh, const VertexFaces& adjacency, const std::vector<int>& seeds, int rings) {
  std::vector<char> inVertex(mesh.positions.size(), 0), inFace(mesh.faces.size(), 0);
  std::vector<int> frontier = seeds, faces;
  for (int v : seeds) inVertex[v] = 1;
  for (int r = 0; r < rings; ++r) {
    std::vector<int> next;
    for (int v : frontier) {
      for (int f : adjacency[v]) {
        if (inFace[f]) continue;
        inFace[f] = 1;
        faces.push_back(f);
        for (int w : mesh.faces[f]) {
          if (!inVertex[w]) {
            inVertex[w] = 1;
            next.push_back(w);
          }
        }
      }
    }
    frontier.swap(next);
  }
  std::sort(faces.begin(), faces.end());

  Submesh sub;
  std::vector<int> local(mesh.positions.size(), -1);
  for (int f : faces) {
    Face t;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.faces[f][k];
      if (local[v] < 0) {
        local[v] = static_cast<int>(sub.vertex.size());
        sub.vertex.push_back(v);
        sub.mesh.positions.push_back(mesh.positions[v]);
      }
      t[k] = local[v];
    }
    sub.mesh.faces.push_back(t);
    sub.face.push_back(f);
  }
  return sub;
}

}  // namespace elastica
