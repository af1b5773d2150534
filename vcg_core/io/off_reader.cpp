// SPDX-License-Identifier: GPL-3.0-or-later
// ASCII OFF (Princeton's Object File Format and its C/N/ST variants): a keyword line, the counts
// "vertices faces edges", one vertex per line (x y z, then colours/normals/texture coordinates we
// ignore), one polygon per line ("n i0 .. in-1", then an optional colour). '#' starts a comment.
#include "readers.h"

#include <array>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace elastica::io::detail {
namespace {

class Lines {
 public:
  explicit Lines(const std::string& path) : in_(path, std::ios::binary) {}
  /// The next line with tokens (comments stripped); false at the end of the file.
  bool next(std::vector<std::string_view>& tokens) {
    while (std::getline(in_, line_)) {
      ++number_;
      const size_t hash = line_.find('#');
      if (hash != std::string::npos) line_.resize(hash);
      tokens = splitTokens(line_);
      if (!tokens.empty()) return true;
    }
    return false;
  }
  long long number() const { return number_; }

 private:
  std::ifstream in_;
  std::string line_;
  long long number_ = 0;
};

}  // namespace

void readOff(const std::string& path, TriMesh& mesh, ReadReport& report) {
  Lines lines(path);
  std::vector<std::string_view> t;
  auto at = [&] { return " (line " + std::to_string(lines.number()) + ")"; };
  if (!lines.next(t)) fail(path, "malformed OFF: no header");
  const std::string_view key = t[0];
  const bool known = key.size() >= 3 && key.substr(key.size() - 3) == "OFF" &&
                     key.find_first_not_of("STCN4n") == key.size() - 3;
  if (!known) fail(path, "malformed OFF: the file does not start with the OFF keyword (found " + quote(key) + ")");
  if (key.find_first_of("4n") != std::string_view::npos)
    fail(path, "unsupported OFF variant " + quote(key) + ": only 3D vertices are supported");
  size_t first = 1;
  if (t.size() > 1 && t[1] == "BINARY") fail(path, "binary OFF is not supported; save it as ASCII OFF or as PLY");
  if (t.size() == 1) {
    if (!lines.next(t)) fail(path, "truncated OFF: no vertex and face counts after the keyword");
    first = 0;
  }
  long long nv = -1, nf = -1;
  if (t.size() < first + 2 || !parseInteger(t[first], nv) || !parseInteger(t[first + 1], nf) || nv < 0 || nf < 0)
    fail(path, "malformed OFF: expected the counts 'vertices faces edges'" + at());
  // Every vertex line takes at least 6 bytes ("0 0 0\n"), every face at least 8 ("3 0 1 2\n"):
  // refuse counts the file cannot hold before allocating for them.
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (nv > INT_MAX / 4 || nf > INT_MAX / 4 || static_cast<unsigned long long>(6 * nv + 8 * nf) > size)
    fail(path, "the OFF header claims " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                   " faces, more than the file's " + std::to_string(size) + " bytes can hold");

  mesh.positions.reserve(static_cast<size_t>(nv));
  for (long long v = 0; v < nv; ++v) {
    if (!lines.next(t))
      fail(path, "truncated OFF: the file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    double x[3];
    for (int k = 0; k < 3; ++k) {
      if (static_cast<size_t>(k) >= t.size() || !parseNumber(t[k], x[k]))
        fail(path, "vertex " + std::to_string(v) + ": expected 3 numbers" +
                       (static_cast<size_t>(k) < t.size() ? ", found " + quote(t[k]) : std::string()) + at());
      if (!std::isfinite(x[k])) fail(path, "vertex " + std::to_string(v) + " has a non-finite coordinate " + quote(t[k]) + at());
    }
    mesh.positions.emplace_back(x[0], x[1], x[2]);
  }

  std::vector<int> corners;
  std::vector<Face>& triangles = mesh.faces;
  for (long long f = 0; f < nf; ++f) {
    if (!lines.next(t))
      fail(path, "truncated OFF: the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    long long n = 0;
    if (!parseInteger(t[0], n)) fail(path, "face " + std::to_string(f) + ": expected a vertex count, found " + quote(t[0]) + at());
    if (n < 3) fail(path, "face " + std::to_string(f) + " has " + std::to_string(n) + " vertices (a face needs at least 3)" + at());
    if (static_cast<size_t>(n) > t.size() - 1)
      fail(path, "face " + std::to_string(f) + " lists " + std::to_string(t.size() - 1) + " of its " + std::to_string(n) +
                     " vertex indices" + at());
    corners.clear();
    for (long long k = 1; k <= n; ++k) {
      long long idx = 0;
      if (!parseInteger(t[k], idx)) fail(path, "face " + std::to_string(f) + ": " + quote(t[k]) + " is not a vertex index" + at());
      if (idx < 0 || idx >= nv)
        fail(path, "face " + std::to_string(f) + " refers to vertex " + std::to_string(idx) + ", but the file has " +
                       std::to_string(nv) + " vertices" + at());
      corners.push_back(static_cast<int>(idx));
    }
    if (n > 3) ++report.polygonsTriangulated;
    for (size_t k = 1; k + 1 < corners.size(); ++k) triangles.push_back({corners[0], corners[k], corners[k + 1]});
  }
}

}  // namespace elastica::io::detail
