// SPDX-License-Identifier: GPL-3.0-or-later
// Writing mesh files (PLY, OFF, OBJ, STL by extension), atomically (atomic_file.h): a failure never leaves a half-written output.
// Our own writer, straight from arrays; its files are byte for byte those vcglib's ExporterPLY
// wrote for the double-precision VcgMesh (same header, property order and number formats), so
// MeshLab reads them as before.
#pragma once

#include <elastica/io/atomic_file.h>
#include <elastica/types.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace elastica {
class VcgMesh;  // vcg_mesh.h; only the overload that writes one needs vcglib
}

namespace elastica::io {

/// A per-vertex or per-face float property, written under `name` (one value per element).
struct PlyFloatProperty {
  std::string name;
  const std::vector<float>* values = nullptr;
};

/// What a PLY file holds besides positions and faces. Each vector that is set has one entry per
/// vertex (or face) of the mesh; properties are written in the order of the members.
struct PlyAttributes {
  const std::vector<Vec3>* vertexNormals = nullptr;                         ///< nx ny nz (double)
  const std::vector<std::array<std::uint8_t, 4>>* vertexColors = nullptr;  ///< red green blue alpha
  const std::vector<double>* vertexQuality = nullptr;                       ///< quality (double)
  std::vector<PlyFloatProperty> vertexFloats;  ///< e.g. mean_curvature, gaussian_curvature
  const std::vector<int>* faceFlags = nullptr;  ///< vcglib's face flags (kPlyFaceSelected: MeshLab's selection)
  std::vector<PlyFloatProperty> faceFloats;    ///< e.g. elastica_new
};

/// Writes `mesh` with `attributes` to `path` atomically (temporary file + rename), binary
/// little-endian or ASCII.
/// @throws IoError on any failure (also an attribute of the wrong length); `path` is then untouched.
void writePly(const std::string& path, const TriMesh& mesh, const PlyAttributes& attributes, bool binary);

/// Writes `mesh` to `path` atomically in the format its extension names (.ply, .off, .obj, .stl,
/// case-insensitive). PLY takes every attribute; OFF takes vertex colours (as COFF) and no other
/// attribute; OBJ and STL take none. `binary` chooses binary PLY and STL (OFF and OBJ are text).
/// @return the names of the attributes set in `attributes` that the format could not carry (empty
///         for PLY), for the caller to tell its user.
/// @throws IoError for an unknown extension (before anything is written) and as writePly.
std::vector<std::string> writeMesh(const std::string& path, const TriMesh& mesh, const PlyAttributes& attributes,
                                   bool binary);

/// Which of a VcgMesh's attributes writePly(path, VcgMesh&, …) writes.
struct PlyWriteOptions {
  bool binary = true;         ///< binary little-endian (default) or ASCII
  bool vertexQuality = false; ///< write per-vertex quality
  bool vertexColor = false;   ///< write per-vertex colour
  bool vertexNormal = false;  ///< write per-vertex normals
  bool curvature = false;     ///< write the "mean_curvature" and "gaussian_curvature" attributes
  bool faceFlags = false;     ///< write per-face flags (MeshLab reads its face selection from them)
  std::vector<std::string> faceFloatAttributes;  ///< per-face float attributes of `m` to write, by name
};

/// Writes the live elements of `m` to `path` atomically, through the array writer above.
/// Include <elastica/vcg_mesh.h> to call it.
/// @throws IoError on any failure; `path` is then untouched.
void writePly(const std::string& path, VcgMesh& m, const PlyWriteOptions& opt);

/// writeMesh for the live elements of `m` and the attributes `opt` asks for (opt.binary as above).
/// @return the attributes asked for that the format of `path` could not carry.
/// @throws IoError as writeMesh; `path` is then untouched.
std::vector<std::string> writeMesh(const std::string& path, VcgMesh& m, const PlyWriteOptions& opt);

}  // namespace elastica::io
