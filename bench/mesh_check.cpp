// SPDX-License-Identifier: GPL-3.0-or-later
// mesh_check MESH...: the independent measures of the cage figures (bench/cage_figures.sh), one
// JSON line per mesh: vertices, faces, genus (from the Euler characteristic of a closed mesh),
// total curvature energy (mixed and barycentric areas), faces crossing another face (vcglib's
// Clean::SelfIntersections, a different implementation from the flow's guard), smallest angle.
#include <elastica/io/mesh_reader.h>
#include <elastica/mesh_curvature.h>
#include <elastica/mesh_quality.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>

using namespace elastica;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: mesh_check MESH...\n");
    return 2;
  }
  for (int i = 1; i < argc; ++i) {
    try {
      const TriMesh m = io::readMesh(argv[i]).mesh;
      VcgMesh vm;
      fromTriMesh(m, vm);
      const MeshCurvature mixed = measureCurvature(m);
      CurvatureMeasureOptions paper;
      paper.area = VertexArea::Barycentric;
      const MeshCurvature bary = measureCurvature(m, paper);
      vcg::tri::UpdateBounding<VcgMesh>::Box(vm);
      std::vector<VcgFace*> hits;
      vcg::tri::Clean<VcgMesh>::SelfIntersections(vm, hits);
      const std::set<VcgFace*> crossing(hits.begin(), hits.end());
      const double minAngle = smallestAngleDegrees(m);
      nlohmann::json j;
      j["file"] = argv[i];
      j["vertices"] = m.vertexCount();
      j["faces"] = m.faceCount();
      j["boundary_edges"] = mixed.boundaryEdges;
      j["genus"] = mixed.boundaryEdges == 0 ? (2 - mixed.eulerCharacteristic) / 2 : -1;
      j["energy"] = mixed.energy;
      j["energy_barycentric"] = bary.energy;
      j["self_intersecting_faces"] = crossing.size();
      j["min_angle_deg"] = minAngle;
      std::cout << j.dump() << "\n";
    } catch (const std::exception& e) {
      std::fprintf(stderr, "mesh_check: %s: %s\n", argv[i], e.what());
      return 1;
    }
  }
  return 0;
}
