// SPDX-License-Identifier: GPL-3.0-or-later
// cgal_region_fair MESH REGION OUT: CGAL's Polygon_mesh_processing::fair() on a selected region,
// for comparison with elastica.fair(V, F, region) (bench/region_sweep.py --cgal). REGION holds
// face indices (whitespace-separated). The moving vertices are those whose faces are all in the
// region and that are not on a border of the mesh: the vertices Elastica's flow moves. fair() runs
// with its defaults (fairing_continuity 1: one sparse solve of the bilaplacian system, the ring
// outside fixed in position and tangent plane). Prints one JSON line: the moving vertices, fair()'s
// success and its seconds (the call alone, not reading, building the Surface_mesh or writing).
// Built only with Debian's libcgal-dev; CGAL is never a dependency of Elastica itself.
#include "guarded_main.h"

#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace elastica;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

std::vector<std::uint8_t> readRegion(const std::string& path, int faces) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<std::uint8_t> selected(faces, 0);
  long long f;
  while (in >> f) {
    if (f < 0 || f >= faces) throw std::runtime_error(path + ": face " + std::to_string(f) + " out of range");
    selected[f] = 1;
  }
  if (!in.eof()) throw std::runtime_error(path + ": not a list of face indices");
  return selected;
}

int run(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: cgal_region_fair MESH REGION OUT\n");
    return 2;
  }
  TriMesh mesh = io::readMesh(argv[1]).mesh;
  const std::vector<std::uint8_t> selected = readRegion(argv[2], mesh.faceCount());
  Mesh sm;
  std::vector<Mesh::Vertex_index> vi;
  for (const Vec3& p : mesh.positions) vi.push_back(sm.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  for (const Face& f : mesh.faces)
    if (sm.add_face(vi[f[0]], vi[f[1]], vi[f[2]]) == Mesh::null_face())
      throw std::runtime_error("the mesh is not an oriented 2-manifold (CGAL's Surface_mesh refused a face)");
  // A vertex moves if every face around it is selected and it is not on a border.
  std::vector<Mesh::Vertex_index> moving;
  for (Mesh::Vertex_index v : sm.vertices()) {
    if (sm.is_isolated(v) || sm.is_border(v)) continue;
    bool all = true;
    for (Mesh::Face_index f : CGAL::faces_around_target(sm.halfedge(v), sm)) all = all && selected[f.idx()];
    if (all) moving.push_back(v);
  }
  const auto t0 = std::chrono::steady_clock::now();
  const bool ok = CGAL::Polygon_mesh_processing::fair(sm, moving);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Surface_mesh keeps the indices of vertices and faces it was given.
  for (Mesh::Vertex_index v : sm.vertices()) {
    const auto& p = sm.point(v);
    mesh.positions[v.idx()] = Vec3(p.x(), p.y(), p.z());
  }
  io::writeMesh(argv[3], mesh, {}, true);
  std::printf("{\"moving\": %zu, \"ok\": %s, \"seconds\": %.6f}\n", moving.size(), ok ? "true" : "false", seconds);
  return ok ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) { return bench::guardedMain("cgal_region_fair", run, argc, argv); }
