// Reading triangle meshes from PLY, OFF, STL (vcglib) and OBJ (tinyobjloader: this vcglib's OBJ
// importer drops every face touching the first vertex) into the double-precision VcgMesh.
#pragma once

#include <elastica/vcg_mesh.h>

#include <string>

namespace elastica::io {

enum class MeshFormat { Ply, Off, Stl, Obj };

/// What reading a file found and did.
struct ReadReport {
  MeshFormat format = MeshFormat::Ply;
  int polygonsTriangulated = 0;    ///< polygons with more than 3 corners split into triangles
  int duplicateVerticesMerged = 0; ///< STL stores unshared corners: coincident ones are merged
  bool hasFaceSelection = false;   ///< the file carried per-face flags (MeshLab's selection)
};

/// The format of `path` from its extension (case-insensitive).
/// @throws IoError for an extension other than .ply, .off, .stl, .obj.
MeshFormat formatFromExtension(const std::string& path);

/// Reads `path` into `m` (cleared first).
/// @throws IoError "<path>: <what>" if the file is missing, a directory, unreadable, empty, of an
///         unknown type, malformed, has non-finite coordinates or out-of-range indices, or holds
///         no triangle.
ReadReport readMesh(const std::string& path, VcgMesh& m);

}  // namespace elastica::io
