// SPDX-License-Identifier: GPL-3.0-or-later
// Reading triangle meshes from PLY, OFF, STL (our own parsers) and OBJ (tinyobjloader: this
// vcglib's OBJ importer drops every face touching the first vertex) straight into the core's
// TriMesh. A VcgMesh overload serves code that works on a vcglib mesh (`elastica run`, `fill`).
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace elastica {
class VcgMesh;  // vcg_mesh.h; only the overload that fills one needs vcglib
}

namespace elastica::io {

enum class MeshFormat { Ply, Off, Stl, Obj };

/// vcglib's face flag bit for "selected" (vcg::face::BitFlags::SELECTED), which MeshLab writes in
/// a PLY face's `flags` property.
constexpr int kPlyFaceSelected = 0x20;

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

/// A mesh file as read and repaired.
struct MeshFile {
  TriMesh mesh;
  /// One byte per face of `mesh`, 1 where the file selected it; empty unless
  /// report.hasFaceSelection.
  std::vector<std::uint8_t> faceSelection;
  ReadReport report;
};

/// The format of `path` from its extension (case-insensitive).
/// @throws IoError for an extension other than .ply, .off, .stl, .obj.
MeshFormat formatFromExtension(const std::string& path);

/// Reads `path`, then checks the mesh and repairs what changes no geometry (merges coincident
/// vertices, removes degenerate and duplicate faces and unreferenced vertices, splits bow-tie
/// vertices); the report counts each repair. Vertices and faces keep the file's order, less what
/// was removed, then the copies made by splitting.
/// @throws IoError "<path>: <what> (<where>)" if the file is missing, a directory, unreadable,
///         empty, of an unknown type, malformed or truncated, claims more elements than it holds,
///         has non-finite coordinates, out-of-range indices, faces of fewer than 3 vertices,
///         non-manifold edges or inconsistently oriented faces, or holds no triangle.
MeshFile readMesh(const std::string& path);

/// readMesh(path) copied into `m` (cleared first): vertex i is m.vert[i], face f is m.face[f],
/// selected faces have their selection flag set. Include <elastica/vcg_mesh.h> to call it.
/// `spare`: room for this fraction more vertices and faces is reserved in `m` (address space only
/// until used), so that elements appended later (a fill's patches) grow `m` in place instead of
/// moving its arrays into larger ones, which holds both at once.
/// @throws IoError as readMesh(path); `m` is then cleared.
ReadReport readMesh(const std::string& path, VcgMesh& m, double spare = 0);

}  // namespace elastica::io
