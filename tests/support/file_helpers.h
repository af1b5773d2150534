// SPDX-License-Identifier: GPL-3.0-or-later
// Scratch files for the I/O and CLI tests.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <vector>
#include <string>

namespace elastica::test {

/// A fresh empty directory under the system temp dir, removed at destruction.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("elastica-test-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// The bytes of a file ("" if it cannot be read).
inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// An ASCII PLY file's vertex table, read independently of vcglib (whose importer cannot load
/// named per-vertex attributes into a mesh): one row per vertex, one column per property.
struct AsciiPly {
  std::vector<std::string> vertexProperties;
  std::vector<std::vector<double>> vertices;
  int faceCount = 0;

  int column(const std::string& name) const {
    for (size_t i = 0; i < vertexProperties.size(); ++i)
      if (vertexProperties[i] == name) return static_cast<int>(i);
    return -1;
  }
};

/// Reads an ASCII PLY; throws std::runtime_error on anything unexpected.
inline AsciiPly readAsciiPly(const std::string& path) {
  std::ifstream in(path);
  std::string line, word;
  AsciiPly ply;
  int vertexCount = 0;
  std::string element;
  if (!std::getline(in, line) || line != "ply") throw std::runtime_error(path + ": not a PLY file");
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream ls(line);
    ls >> word;
    if (word == "format" && line.find("ascii") == std::string::npos) throw std::runtime_error(path + ": not ASCII");
    if (word == "element") {
      ls >> element;
      (element == "vertex" ? vertexCount : ply.faceCount) = [&] { int n; ls >> n; return n; }();
    } else if (word == "property" && element == "vertex") {
      std::string type, name;
      ls >> type >> name;
      ply.vertexProperties.push_back(name);
    }
  }
  for (int v = 0; v < vertexCount; ++v) {
    std::vector<double> row(ply.vertexProperties.size());
    for (double& x : row) in >> x;
    if (!in) throw std::runtime_error(path + ": truncated vertex table");
    ply.vertices.push_back(std::move(row));
  }
  return ply;
}

}  // namespace elastica::test
