// File handling shared by the subcommands: reading with notes on stderr, atomic PLY output.
#pragma once

#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/types.h>

#include <string>

namespace elastica::cli {

/// Reads `path` into `m`, telling on stderr what was repaired on the way (merged STL corners,
/// triangulated polygons). @throws IoError.
io::ReadReport loadMesh(const std::string& path, VcgMesh& m);

/// Human-readable count, e.g. "1 face" / "3 faces".
std::string plural(std::size_t n, const std::string& word);

}  // namespace elastica::cli
