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
  int polygonsTriangulated = 0;         ///< polygons with more than 3 corners split into triangles
  int duplicateVerticesMerged = 0;      ///< coincident vertices merged (STL stores unshared corners)
  int degenerateFacesRemoved = 0;       ///< faces repeating a vertex (also after merging), removed
  int duplicateFacesRemoved = 0;        ///< second copies of a face on the same three vertices, removed
  int nonManifoldVerticesSplit = 0;     ///< bow-tie vertices split into one vertex per fan of faces
  int unreferencedVerticesRemoved = 0;  ///< vertices no face used, dropped
  bool hasFaceSelection = false;   ///< the file carried per-face flags (MeshLab's selection)
};

/// The format of `path` from its extension (case-insensitive).
/// @throws IoError for an extension other than .ply, .off, .stl, .obj.
MeshFormat formatFromExtension(const std::string& path);

/// Reads `path` into `m` (cleared first), then checks the mesh and repairs what changes no
/// geometry (merges coincident vertices, removes degenerate and duplicate faces and unreferenced
/// vertices, splits bow-tie vertices); the report counts each repair.
/// @throws IoError "<path>: <what> (<where>)" if the file is missing, a directory, unreadable,
///         empty, of an unknown type, malformed or truncated, claims more elements than it holds,
///         has non-finite coordinates, out-of-range indices, faces of fewer than 3 vertices,
///         non-manifold edges or inconsistently oriented faces, or holds no triangle.
ReadReport readMesh(const std::string& path, VcgMesh& m);

}  // namespace elastica::io
