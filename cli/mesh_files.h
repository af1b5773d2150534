// File handling shared by the subcommands: reading with notes on stderr, atomic PLY output.
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

/// The same into a vcglib mesh, for the commands that work on one (`run`, `fill`). @throws IoError.
io::ReadReport loadMesh(const std::string& path, VcgMesh& m);

/// Writes `mesh` as PLY with quality = H (the reported sign, +1/r on a sphere:
/// MeshCurvature::H) and the mean_curvature / gaussian_curvature attributes, plus the colour ramp
/// by H if `color`. @throws IoError.
void writeCurvaturePly(const std::string& path, const TriMesh& mesh, const std::vector<double>& reportedH,
                       const std::vector<double>& K, bool ascii, bool color);

/// Human-readable count, e.g. "1 face" / "3 faces".
std::string plural(std::size_t n, const std::string& word);

}  // namespace elastica::cli
