// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh_files.h"

#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <iostream>

namespace elastica::cli {

std::string plural(std::size_t n, const std::string& word) {
  if (n == 1) return "1 " + word;
  // vertex → vertices, the one irregular plural we print.
  const bool ex = word.size() > 2 && word.compare(word.size() - 2, 2, "ex") == 0;
  return std::to_string(n) + " " + (ex ? word.substr(0, word.size() - 2) + "ices" : word + "s");
}

namespace {
void noteDropped(const std::string& path, const std::vector<std::string>& dropped) {
  if (dropped.empty()) return;
  std::string names;
  for (const std::string& d : dropped) names += (names.empty() ? "" : ", ") + d;
  std::cerr << "note: " << path << ": the format holds no " << names << "; written without "
            << (dropped.size() == 1 ? "it" : "them") << " (use .ply to keep them)\n";
}
}  // namespace

void checkMeshOutput(const std::string& output, const std::string& input) {
  io::formatFromExtension(output);
  io::checkOutputPath(output, input);
}

void writeMeshFile(const std::string& path, const TriMesh& mesh, const io::PlyAttributes& attributes, bool binary) {
  noteDropped(path, io::writeMesh(path, mesh, attributes, binary));
}

void writeMeshFile(const std::string& path, VcgMesh& m, const io::PlyWriteOptions& opt) {
  noteDropped(path, io::writeMesh(path, m, opt));
}

void writeCurvatureMesh(const std::string& path, const TriMesh& mesh, const std::vector<double>& reportedH,
                       const std::vector<double>& K, bool ascii, bool color) {
  const std::vector<float> h(reportedH.begin(), reportedH.end()), k(K.begin(), K.end());
  std::vector<std::array<std::uint8_t, 4>> colors;
  io::PlyAttributes a;
  if (color) {
    colors.reserve(reportedH.size());
    for (const vcg::Color4b& c : qualityColorRamp(reportedH)) colors.push_back({c[0], c[1], c[2], c[3]});
    a.vertexColors = &colors;
  }
  a.vertexQuality = &reportedH;
  a.vertexFloats = {{"mean_curvature", &h}, {"gaussian_curvature", &k}};
  writeMeshFile(path, mesh, a, !ascii);
}

namespace {
void noteRepairs(const std::string& path, const io::ReadReport& r) {
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
}
}  // namespace

io::MeshFile loadMesh(const std::string& path) {
  io::MeshFile file = io::readMesh(path);
  noteRepairs(path, file.report);
  return file;
}

io::ReadReport loadMesh(const std::string& path, VcgMesh& m, double spare) {
  const io::ReadReport r = io::readMesh(path, m, spare);
  noteRepairs(path, r);
  return r;
}

}  // namespace elastica::cli
