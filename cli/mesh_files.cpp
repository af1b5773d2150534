#include "mesh_files.h"

#include <elastica/vcg_adapter.h>

#include <iostream>

namespace elastica::cli {

std::string plural(std::size_t n, const std::string& word) {
  if (n == 1) return "1 " + word;
  // vertex → vertices, the one irregular plural we print.
  const bool ex = word.size() > 2 && word.compare(word.size() - 2, 2, "ex") == 0;
  return std::to_string(n) + " " + (ex ? word.substr(0, word.size() - 2) + "ices" : word + "s");
}

void writeCurvaturePly(const std::string& path, VcgMesh& m, const std::vector<double>& reportedH,
                       const std::vector<double>& K, bool ascii, bool color) {
  storeCurvature(m, reportedH, K);
  io::PlyWriteOptions w;
  w.binary = !ascii;
  w.vertexQuality = w.curvature = true;
  w.vertexColor = color;
  io::writePly(path, m, w);
}

io::ReadReport loadMesh(const std::string& path, VcgMesh& m) {
  io::ReadReport r = io::readMesh(path, m);
  auto note = [&](int n, const std::string& what) {
    if (n > 0) std::cerr << "note: " << path << ": " << what << "\n";
  };
  const bool stl = r.format == io::MeshFormat::Stl;
  note(r.duplicateVerticesMerged, "merged " + plural(r.duplicateVerticesMerged, stl ? "coincident STL corner" : "duplicate vertex") +
                                      " into shared vertices");
  note(r.polygonsTriangulated, "split " + plural(r.polygonsTriangulated, "polygon") + " into triangles");
  note(r.degenerateFacesRemoved, "removed " + plural(r.degenerateFacesRemoved, "degenerate face") + " (a vertex used twice)");
  note(r.duplicateFacesRemoved, "removed " + plural(r.duplicateFacesRemoved, "duplicate face"));
  note(r.nonManifoldVerticesSplit, "split " + plural(r.nonManifoldVerticesSplit, "non-manifold vertex") +
                                       " (several fans of faces meeting at one point) into one vertex per fan");
  note(r.unreferencedVerticesRemoved, "removed " + plural(r.unreferencedVerticesRemoved, "unreferenced vertex"));
  return r;
}

}  // namespace elastica::cli
