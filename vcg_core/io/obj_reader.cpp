// SPDX-License-Identifier: GPL-3.0-or-later
// Wavefront OBJ through tinyobjloader (this vcglib's OBJ importer drops every face touching the
// first vertex). tinyobjloader turns a coordinate it cannot parse ("nan", "abc", a missing z)
// into 0 without a word, so the 'v' lines are checked here first.
#include "readers.h"

#include <tiny_obj_loader.h>

#include <cctype>
#include <cmath>
#include <fstream>

namespace elastica::io::detail {
namespace {

void checkVertexLines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long lineNo = 0, vertex = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const auto t = splitTokens(line);
    if (t.empty() || t[0] != "v") continue;
    const std::string where = "vertex " + std::to_string(vertex) + " (line " + std::to_string(lineNo) + ")";
    if (t.size() < 4) fail(path, where + " has " + std::to_string(t.size() - 1) + " coordinates (needs 3)");
    for (int k = 1; k <= 3; ++k) {
      double x = 0;
      if (!parseNumber(t[k], x)) fail(path, where + ": " + quote(t[k]) + " is not a number");
      if (!std::isfinite(x)) fail(path, where + " has a non-finite coordinate " + quote(t[k]));
    }
    ++vertex;
  }
}

}  // namespace

void readObj(const std::string& path, TriMesh& mesh, ReadReport& report) {
  checkVertexLines(path);
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
  mesh.positions.reserve(nv);
  for (size_t i = 0; i < nv; ++i) mesh.positions.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);

  size_t triangles = 0, face = 0;
  for (const auto& shape : reader.GetShapes()) {
    // tinyobjloader keeps each face's size in a byte: a face of 256 or more corners wraps around.
    size_t cornersListed = 0;
    for (unsigned n : shape.mesh.num_face_vertices) cornersListed += n;
    if (cornersListed != shape.mesh.indices.size())
      fail(path, "a face in object " + quote(shape.name, 40) + " has more than 255 vertices, which this reader cannot hold");
    for (unsigned n : shape.mesh.num_face_vertices) {
      if (n < 3) fail(path, "face " + std::to_string(face) + " has " + std::to_string(n) + " vertices (a face needs at least 3)");
      triangles += n - 2;
      ++face;
    }
  }
  mesh.faces.reserve(triangles);
  face = 0;
  for (const auto& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (unsigned n : shape.mesh.num_face_vertices) {
      auto vertex = [&](size_t k) {
        const int idx = shape.mesh.indices[offset + k].vertex_index;
        if (idx < 0 || static_cast<size_t>(idx) >= nv)
          fail(path, "face " + std::to_string(face) + " refers to vertex " + std::to_string(idx + 1) +
                         " (OBJ counts from 1), but the file has " + std::to_string(nv) + " vertices");
        return idx;
      };
      if (n > 3) ++report.polygonsTriangulated;
      for (unsigned k = 1; k + 1 < n; ++k) mesh.faces.push_back({vertex(0), vertex(k), vertex(k + 1)});
      offset += n;
      ++face;
    }
  }
}

}  // namespace elastica::io::detail
