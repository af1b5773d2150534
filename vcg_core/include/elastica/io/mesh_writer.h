// Writing PLY files, atomically (atomic_file.h): a failure never leaves a half-written output.
#pragma once

#include <elastica/io/atomic_file.h>
#include <elastica/vcg_mesh.h>

#include <string>
#include <vector>

namespace elastica::io {

struct PlyWriteOptions {
  bool binary = true;         ///< binary little-endian (default) or ASCII
  bool vertexQuality = false; ///< write per-vertex quality
  bool vertexColor = false;   ///< write per-vertex colour
  bool vertexNormal = false;  ///< write per-vertex normals
  bool curvature = false;     ///< write the "mean_curvature" and "gaussian_curvature" attributes
  bool faceFlags = false;     ///< write per-face flags (MeshLab reads its face selection from them)
  std::vector<std::string> faceFloatAttributes;  ///< per-face float attributes of `m` to write, by name
};

/// Writes `m` to `path` atomically (temporary file + rename).
/// @throws IoError on any failure; `path` is then untouched.
void writePly(const std::string& path, VcgMesh& m, const PlyWriteOptions& opt);

}  // namespace elastica::io
