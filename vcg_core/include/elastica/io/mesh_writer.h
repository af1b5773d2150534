// Writing PLY files so that a failure never leaves a half-written output: the data goes to a
// temporary file in the destination directory, which is renamed over the destination at the end.
#pragma once

#include <elastica/vcg_mesh.h>

#include <string>

namespace elastica::io {

struct PlyWriteOptions {
  bool binary = true;         ///< binary little-endian (default) or ASCII
  bool vertexQuality = false; ///< write per-vertex quality
  bool vertexColor = false;   ///< write per-vertex colour
  bool vertexNormal = false;  ///< write per-vertex normals
  bool curvature = false;     ///< write the "mean_curvature" and "gaussian_curvature" attributes
};

/// Checks, before any work is done, that `output` can be written and is not `input`.
/// @throws IoError naming the problem (missing directory, not writable, a directory, same file).
void checkOutputPath(const std::string& output, const std::string& input = {});

/// Writes `m` to `path` atomically (temporary file + rename).
/// @throws IoError on any failure; `path` is then untouched.
void writePly(const std::string& path, VcgMesh& m, const PlyWriteOptions& opt);

}  // namespace elastica::io
