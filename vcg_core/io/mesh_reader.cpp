// SPDX-License-Identifier: GPL-3.0-or-later
#include "readers.h"

#include <elastica/errors.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace elastica::io {
namespace fs = std::filesystem;

namespace detail {
void fail(const std::string& path, const std::string& what) { throw IoError(path + ": " + what); }
}  // namespace detail

using detail::fail;

MeshFormat formatFromExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".obj") return MeshFormat::Obj;
  throw IoError(path + ": unknown mesh file extension " + detail::quote(ext) + " (expected .ply, .off, .stl or .obj)");
}

MeshFile readMesh(const std::string& path) {
  MeshFile file;
  ReadReport& report = file.report;
  report.format = formatFromExtension(path);
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) fail(path, "no such file");
  if (fs::is_directory(status)) fail(path, "is a directory, not a mesh file");
  if (!fs::is_regular_file(status)) fail(path, "not a regular file");
  if (!std::ifstream(path, std::ios::binary)) fail(path, "cannot open for reading (permission denied?)");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) fail(path, "cannot read its size (" + ec.message() + ")");
  if (size == 0) fail(path, "empty file");

  switch (report.format) {
    case MeshFormat::Ply: detail::readPly(path, size, file.mesh, file.faceSelection, report); break;
    case MeshFormat::Off: detail::readOff(path, file.mesh, report); break;
    case MeshFormat::Stl: detail::readStl(path, file.mesh); break;
    case MeshFormat::Obj: detail::readObj(path, file.mesh, report); break;
  }
  detail::checkAndRepair(path, file.mesh, file.faceSelection, report);
  return file;
}

}  // namespace elastica::io
