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

void writeCurvaturePly(const std::string& path, VcgMesh& m, const std::vector<double>& paperH,
                       const std::vector<double>& K, bool ascii, bool color) {
  storeCurvature(m, paperH, K);
  io::PlyWriteOptions w;
  w.binary = !ascii;
  w.vertexQuality = w.curvature = true;
  w.vertexColor = color;
  io::writePly(path, m, w);
}

io::ReadReport loadMesh(const std::string& path, VcgMesh& m) {
  io::ReadReport report = io::readMesh(path, m);
  if (report.duplicateVerticesMerged > 0)
    std::cerr << "note: " << path << ": merged " << plural(report.duplicateVerticesMerged, "coincident STL corner")
              << " into shared vertices\n";
  if (report.polygonsTriangulated > 0)
    std::cerr << "note: " << path << ": split " << plural(report.polygonsTriangulated, "polygon")
              << " into triangles\n";
  return report;
}

}  // namespace elastica::cli
