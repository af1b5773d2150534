// SPDX-License-Identifier: GPL-3.0-or-later
#include "cgal_fill.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>
#include <vector>

namespace elastica::bench {

int cgalFillHoles(TriMesh& mesh) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  Mesh sm;
  std::vector<Mesh::Vertex_index> vi;
  for (const Vec3& p : mesh.positions) vi.push_back(sm.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  for (const Face& f : mesh.faces) sm.add_face(vi[f[0]], vi[f[1]], vi[f[2]]);

  std::vector<Mesh::Halfedge_index> borders;
  std::vector<char> seen(sm.number_of_halfedges(), 0);
  for (Mesh::Halfedge_index h : sm.halfedges()) {
    if (!sm.is_border(h) || seen[h.idx()]) continue;
    borders.push_back(h);
    for (Mesh::Halfedge_index g : CGAL::halfedges_around_face(h, sm)) seen[g.idx()] = 1;
  }
  int filled = 0;
  for (Mesh::Halfedge_index h : borders) {
    std::vector<Mesh::Face_index> faces;
    std::vector<Mesh::Vertex_index> vertices;
    const auto result = CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole(
        sm, h, std::back_inserter(faces), std::back_inserter(vertices));
    filled += std::get<0>(result) ? 1 : 0;
  }
  // Surface_mesh appends: old indices are unchanged.
  mesh.positions.clear();
  for (Mesh::Vertex_index v : sm.vertices()) {
    const auto& p = sm.point(v);
    mesh.positions.emplace_back(p.x(), p.y(), p.z());
  }
  mesh.faces.clear();
  for (Mesh::Face_index f : sm.faces()) {
    Face t;
    int k = 0;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm)) t[k++] = static_cast<int>(v.idx());
    mesh.faces.push_back(t);
  }
  return filled;
}

}  // namespace elastica::bench
