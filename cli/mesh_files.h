// SPDX-License-Identifier: GPL-3.0-or-later
// File handling shared by the subcommands: reading with notes on stderr, atomic output in the
// format the output's extension names.
#pragma once

#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/types.h>

#include <string>
#include <vector>

namespace elastica::cli {

/// Reads `path` (io::readMesh), telling on stderr what was repaired on the way (merged vertices,
/// triangulated polygons, removed faces, split vertices). @throws IoError.
io::MeshFile loadMesh(const std::string& path);

/// The same into a vcglib mesh, for the commands that work on one (`run`, `fill`), with room
/// reserved for `spare` times as many elements more (io::readMesh). @throws IoError.
io::ReadReport loadMesh(const std::string& path, VcgMesh& m, double spare = 0);

/// The help of every command's -o and --ascii.
inline constexpr const char* kOutputHelp = "output mesh; its extension chooses the format: .ply (every attribute), "
                                           ".off, .obj or .stl (positions and faces)";
inline constexpr const char* kAsciiHelp = "write ASCII PLY or STL (default: binary; OFF and OBJ are always text)";

/// Checks, before any work, that `output` names a mesh format (.ply, .off, .obj, .stl) and can be
/// written, and is not `input`. @throws IoError.
void checkMeshOutput(const std::string& output, const std::string& input = {});

/// io::writeMesh, then one note on stderr naming what the format could not carry. @throws IoError.
void writeMeshFile(const std::string& path, const TriMesh& mesh, const io::PlyAttributes& attributes, bool binary);
void writeMeshFile(const std::string& path, VcgMesh& m, const io::PlyWriteOptions& opt);

/// Writes `mesh` (in the format of `path`) with quality = H (the reported sign, +1/r on a sphere:
/// MeshCurvature::H) and the mean_curvature / gaussian_curvature attributes, plus the colour ramp
/// by H if `color`. @throws IoError.
void writeCurvatureMesh(const std::string& path, const TriMesh& mesh, const std::vector<double>& reportedH,
                       const std::vector<double>& K, bool ascii, bool color);

/// Human-readable count, e.g. "1 face" / "3 faces".
std::string plural(std::size_t n, const std::string& word);

}  // namespace elastica::cli
