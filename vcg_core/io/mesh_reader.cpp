#include <elastica/errors.h>
#include <elastica/io/mesh_reader.h>

#include <tiny_obj_loader.h>
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>
#include <wrap/io_trimesh/import_stl.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace elastica::io {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw IoError(path + ": " + what); }

void readObj(const std::string& path, VcgMesh& m, ReadReport& report) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // we fan-triangulate ourselves, to count and to check indices
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    std::string msg = reader.Error();
    while (!msg.empty() && std::isspace(static_cast<unsigned char>(msg.back()))) msg.pop_back();
    fail(path, "malformed OBJ" + (msg.empty() ? std::string() : " (" + msg + ")"));
  }
  const auto& xyz = reader.GetAttrib().vertices;
  const size_t nv = xyz.size() / 3;
  auto vi = vcg::tri::Allocator<VcgMesh>::AddVertices(m, nv);
  for (size_t i = 0; i < nv; ++i, ++vi) vi->P() = vcg::Point3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);

  size_t triangles = 0;
  for (const auto& shape : reader.GetShapes()) {
    for (unsigned char n : shape.mesh.num_face_vertices) {
      if (n < 3) fail(path, "OBJ face with fewer than 3 vertices");
      triangles += n - 2;
    }
  }
  auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(m, triangles);
  for (const auto& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (unsigned char n : shape.mesh.num_face_vertices) {
      auto vertex = [&](size_t k) {
        const int idx = shape.mesh.indices[offset + k].vertex_index;
        if (idx < 0 || static_cast<size_t>(idx) >= nv)
          fail(path, "OBJ face references vertex " + std::to_string(idx + 1) + " of " + std::to_string(nv));
        return &m.vert[idx];
      };
      if (n > 3) ++report.polygonsTriangulated;
      for (unsigned k = 1; k + 1 < n; ++k, ++fi) {
        fi->V(0) = vertex(0);
        fi->V(1) = vertex(k);
        fi->V(2) = vertex(k + 1);
      }
      offset += n;
    }
  }
}

}  // namespace

MeshFormat formatFromExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".obj") return MeshFormat::Obj;
  throw IoError(path + ": unknown mesh file extension '" + ext + "' (expected .ply, .off, .stl or .obj)");
}

ReadReport readMesh(const std::string& path, VcgMesh& m) {
  ReadReport report;
  report.format = formatFromExtension(path);
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) fail(path, "no such file");
  if (fs::is_directory(status)) fail(path, "is a directory, not a mesh file");
  if (!fs::is_regular_file(status)) fail(path, "not a regular file");
  if (!std::ifstream(path, std::ios::binary)) fail(path, "cannot open for reading (permission denied?)");
  if (fs::file_size(path, ec) == 0) fail(path, "empty file");

  m.Clear();
  int mask = 0;
  switch (report.format) {
    case MeshFormat::Ply: {
      const int err = vcg::tri::io::ImporterPLY<VcgMesh>::Open(m, path.c_str(), mask);
      if (err != 0) fail(path, std::string("malformed PLY (") + vcg::tri::io::ImporterPLY<VcgMesh>::ErrorMsg(err) + ")");
      report.hasFaceSelection = (mask & vcg::tri::io::Mask::IOM_FACEFLAGS) != 0;
      break;
    }
    case MeshFormat::Off: {
      const int err = vcg::tri::io::ImporterOFF<VcgMesh>::Open(m, path.c_str(), mask);
      if (err != 0) fail(path, std::string("malformed OFF (") + vcg::tri::io::ImporterOFF<VcgMesh>::ErrorMsg(err) + ")");
      break;
    }
    case MeshFormat::Stl: {
      const int err = vcg::tri::io::ImporterSTL<VcgMesh>::Open(m, path.c_str(), mask);
      if (err != 0) fail(path, std::string("malformed STL (") + vcg::tri::io::ImporterSTL<VcgMesh>::ErrorMsg(err) + ")");
      // STL stores each triangle's corners separately: merge coincident ones into shared vertices.
      report.duplicateVerticesMerged = vcg::tri::Clean<VcgMesh>::RemoveDuplicateVertex(m);
      vcg::tri::Allocator<VcgMesh>::CompactEveryVector(m);
      break;
    }
    case MeshFormat::Obj:
      readObj(path, m, report);
      break;
  }

  for (size_t i = 0; i < m.vert.size(); ++i) {
    const auto& p = m.vert[i].cP();
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail(path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  if (m.fn == 0) fail(path, "no triangles (" + std::to_string(m.vn) + " vertices, 0 faces)");
  return report;
}

}  // namespace elastica::io
