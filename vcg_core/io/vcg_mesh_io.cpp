// SPDX-License-Identifier: GPL-3.0-or-later
// The VcgMesh overloads of readMesh and writePly: the only place mesh files meet vcglib. Reading
// copies the TriMesh read into the vcglib mesh once; writing copies its live elements and the
// attributes asked for into arrays once, for the array writer.
#include <elastica/errors.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

namespace elastica::io {

static_assert(kPlyFaceSelected == VcgFace::SELECTED, "the PLY face flag for selection is vcglib's");

ReadReport readMesh(const std::string& path, VcgMesh& m, double spare) {
  m.Clear();
  const MeshFile file = readMesh(path);
  if (spare > 0) {  // `m` is empty: no pointer into its arrays yet
    m.vert.reserve(static_cast<size_t>(file.mesh.positions.size() * (1 + spare)));
    m.face.reserve(static_cast<size_t>(file.mesh.faces.size() * (1 + spare)));
  }
  fromTriMesh(file.mesh, m);
  for (size_t f = 0; f < file.faceSelection.size(); ++f)
    if (file.faceSelection[f]) m.face[f].SetS();
  return file.report;
}

namespace {

// Calls write(mesh, attributes) with the live elements of `m` and the attributes `opt` asks for.
template <class Write>
auto withArrays(const std::string& path, VcgMesh& m, const PlyWriteOptions& opt, Write write) {
  TriMesh mesh = toTriMesh(m);
  std::vector<Vec3> normals;
  std::vector<std::array<std::uint8_t, 4>> colors;
  std::vector<double> quality;
  std::vector<int> flags;
  std::vector<std::vector<float>> vertexValues, faceValues;
  PlyAttributes a;
  for (const auto& v : m.vert) {
    if (v.IsD()) continue;
    if (opt.vertexNormal) normals.emplace_back(v.cN()[0], v.cN()[1], v.cN()[2]);
    if (opt.vertexColor) colors.push_back({v.cC()[0], v.cC()[1], v.cC()[2], v.cC()[3]});
    if (opt.vertexQuality) quality.push_back(v.cQ());
  }
  if (opt.vertexNormal) a.vertexNormals = &normals;
  if (opt.vertexColor) a.vertexColors = &colors;
  if (opt.vertexQuality) a.vertexQuality = &quality;
  if (opt.faceFlags) {
    for (const auto& f : m.face)
      if (!f.IsD()) flags.push_back(f.cFlags());
    a.faceFlags = &flags;
  }
  // A named float attribute's values on the live elements of `elements`.
  auto liveValues = [](auto& elements, auto handle) {
    std::vector<float> values;
    for (auto it = elements.begin(); it != elements.end(); ++it)
      if (!it->IsD()) values.push_back(handle[it]);
    return values;
  };
  auto vertexAttribute = [&](const std::string& name) {
    if (!vcg::tri::HasPerVertexAttribute(m, name)) throw IoError(path + ": the mesh has no vertex attribute " + name);
    vertexValues.push_back(liveValues(m.vert, vcg::tri::Allocator<VcgMesh>::FindPerVertexAttribute<float>(m, name)));
  };
  auto faceAttribute = [&](const std::string& name) {
    if (!vcg::tri::HasPerFaceAttribute(m, name)) throw IoError(path + ": the mesh has no face attribute " + name);
    faceValues.push_back(liveValues(m.face, vcg::tri::Allocator<VcgMesh>::FindPerFaceAttribute<float>(m, name)));
  };
  std::vector<std::string> vertexNames, faceNames = opt.faceFloatAttributes;
  if (opt.curvature) vertexNames = {"mean_curvature", "gaussian_curvature"};
  vertexValues.reserve(vertexNames.size());  // the pointers below stay valid
  faceValues.reserve(faceNames.size());
  for (const std::string& name : vertexNames) vertexAttribute(name);
  for (const std::string& name : faceNames) faceAttribute(name);
  for (size_t i = 0; i < vertexNames.size(); ++i) a.vertexFloats.push_back({vertexNames[i], &vertexValues[i]});
  for (size_t i = 0; i < faceNames.size(); ++i) a.faceFloats.push_back({faceNames[i], &faceValues[i]});
  return write(mesh, a);
}

}  // namespace

void writePly(const std::string& path, VcgMesh& m, const PlyWriteOptions& opt) {
  withArrays(path, m, opt, [&](const TriMesh& mesh, const PlyAttributes& a) { writePly(path, mesh, a, opt.binary); });
}

std::vector<std::string> writeMesh(const std::string& path, VcgMesh& m, const PlyWriteOptions& opt) {
  formatFromExtension(path);  // an unknown extension fails before the copy
  return withArrays(path, m, opt, [&](const TriMesh& mesh, const PlyAttributes& a) { return writeMesh(path, mesh, a, opt.binary); });
}

}  // namespace elastica::io
