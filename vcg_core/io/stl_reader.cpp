// SPDX-License-Identifier: GPL-3.0-or-later
// STL, binary and ASCII. Binary: an 80-byte label, a little-endian uint32 triangle count, then
// 50 bytes per triangle (normal, three corners as float32, a 16-bit attribute). ASCII: "solid",
// then "facet normal ... / outer loop / vertex x y z (x3) / endloop / endfacet", "endsolid".
// Many binary files start their label with "solid" too: a file whose size is exactly what its
// count says is binary. Every triangle gets its own three vertices; checkAndRepair merges them.
#include "readers.h"

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace elastica::io::detail {
namespace {

constexpr std::uintmax_t kLabel = 80, kTriangleBytes = 50;

// Every corner its own vertex: triangle t is (3t, 3t + 1, 3t + 2).
void addTriangles(TriMesh& mesh) {
  const int n = static_cast<int>(mesh.positions.size() / 3);
  mesh.faces.resize(static_cast<size_t>(n));
  for (int t = 0; t < n; ++t) mesh.faces[t] = {3 * t, 3 * t + 1, 3 * t + 2};
}

void readBinary(const std::string& path, TriMesh& mesh, std::uint32_t count) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(kLabel + 4);
  std::vector<Vec3>& corners = mesh.positions;
  corners.reserve(3 * size_t(count));
  unsigned char rec[kTriangleBytes];
  for (std::uint32_t t = 0; t < count; ++t) {
    if (!in.read(reinterpret_cast<char*>(rec), kTriangleBytes))
      fail(path, "truncated binary STL: the file ends in triangle " + std::to_string(t));
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      for (int c = 0; c < 3; ++c) {
        const unsigned char* b = rec + 12 + 12 * k + 4 * c;  // skip the 12-byte normal
        const std::uint32_t bits = b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t(b[3]) << 24);
        std::memcpy(&xyz[c], &bits, 4);
      }
      corners.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
  }
  addTriangles(mesh);
}

void readAscii(const std::string& path, TriMesh& mesh) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long lineNo = 0;
  std::vector<Vec3>& corners = mesh.positions;
  int inLoop = -1;  // corners read in the current loop; -1 outside a loop
  auto at = [&] { return " (line " + std::to_string(lineNo) + ")"; };
  while (std::getline(in, line)) {
    ++lineNo;
    const auto t = splitTokens(line);
    if (t.empty()) continue;
    const std::string_view key = t[0];
    if (key == "vertex") {
      if (inLoop < 0) fail(path, "malformed ASCII STL: 'vertex' outside an 'outer loop'" + at());
      if (inLoop == 3) fail(path, "ASCII STL facet " + std::to_string(corners.size() / 3) + " has more than 3 vertices" + at());
      double x[3];
      for (int k = 0; k < 3; ++k)
        if (t.size() < 4 || !parseNumber(t[k + 1], x[k]))
          fail(path, "malformed ASCII STL: 'vertex' needs 3 numbers" + at());
      corners.emplace_back(x[0], x[1], x[2]);
      ++inLoop;
    } else if (key == "outer") {
      inLoop = 0;
    } else if (key == "endloop") {
      if (inLoop != 3)
        fail(path, "ASCII STL facet " + std::to_string(corners.size() / 3) + " has " + std::to_string(std::max(inLoop, 0)) +
                       " vertices (a facet needs 3)" + at());
      inLoop = -1;
    } else if (key != "solid" && key != "facet" && key != "endfacet" && key != "endsolid") {
      fail(path, "malformed ASCII STL: unexpected " + quote(key) + at());
    }
  }
  if (inLoop >= 0) fail(path, "truncated ASCII STL: the file ends inside facet " + std::to_string(corners.size() / 3));
  addTriangles(mesh);
}

}  // namespace

void readStl(const std::string& path, TriMesh& mesh) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  char head[kLabel + 4] = {};
  in.read(head, sizeof head);
  const size_t got = static_cast<size_t>(in.gcount());
  if (got == sizeof head) {
    const auto* b = reinterpret_cast<const unsigned char*>(head + kLabel);
    const std::uint32_t count = b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t(b[3]) << 24);
    if (size == kLabel + 4 + kTriangleBytes * std::uintmax_t(count)) return readBinary(path, mesh, count);
  }
  const auto text = splitTokens(std::string_view(head, got));
  if (!text.empty() && text[0] == "solid") return readAscii(path, mesh);
  if (got < sizeof head) fail(path, "malformed STL: " + std::to_string(size) + " bytes, too short for a binary STL header and not ASCII STL");
  const auto* b = reinterpret_cast<const unsigned char*>(head + kLabel);
  const std::uint32_t count = b[0] | (b[1] << 8) | (b[2] << 16) | (std::uint32_t(b[3]) << 24);
  fail(path, "malformed binary STL: the header says " + std::to_string(count) + " triangles (" +
                 std::to_string(kLabel + 4 + kTriangleBytes * std::uintmax_t(count)) + " bytes), but the file has " +
                 std::to_string(size) + " bytes");
}

}  // namespace elastica::io::detail
