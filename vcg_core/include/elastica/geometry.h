// SPDX-License-Identifier: GPL-3.0-or-later
// Per-step geometry of a mesh: everything the discrete operators need, computed once per step
// into flat arrays from the positions and a Topology. Nobody recomputes a cotangent twice.
#pragma once

#include <elastica/topology.h>
#include <elastica/types.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace elastica {

/// How the area A_i attached to vertex i is measured (the denominator of Δ_B, H and K).
enum class VertexArea {
  /// Meyer et al.'s mixed Voronoi area (default): H and K converge under refinement
  /// (worst-vertex error of H on a 10,242-vertex icosphere: 0.003 %).
  Mixed,
  /// The paper's A/3 (one third of the incident triangles' area), for reproducing the paper:
  /// does not converge at irregular vertices (14.6 % on the same icosphere).
  Barycentric,
};

/// What a geometry pass found degenerate. Degenerate elements give finite values (zero
/// contributions) and are counted here, never NaN.
struct DegeneracyCounts {
  static constexpr double kRelativeArea = 1e-12;    ///< of the mean edge length squared
  static constexpr double kRelativeLength = 1e-12;  ///< of the mean edge length
  std::size_t zeroAreaFaces = 0;     ///< faces with area at most kRelativeArea · (mean edge length)²
  std::size_t zeroLengthEdges = 0;   ///< edges at most kRelativeLength · mean edge length long
  std::size_t zeroAreaVertices = 0;  ///< vertices in faces but with ~zero area or no normal: H = K = 0
  std::size_t isolatedVertices = 0;  ///< vertices in no face: inactive everywhere
  std::size_t total() const { return zeroAreaFaces + zeroLengthEdges + zeroAreaVertices + isolatedVertices; }
};

/// Cached geometric quantities of one configuration of the mesh.
struct Geometry {
  VertexArea areaType = VertexArea::Mixed;
  double meanEdgeLength = 0;  ///< the length scale that every tolerance is relative to
  double minFaceArea = 0;     ///< smallest non-degenerate face area (the paper's A_k)

  std::vector<double> faceArea;      ///< per face
  std::vector<Vec3> faceNormal;      ///< per face, unit (zero for degenerate faces)
  std::vector<double> cornerDot;     ///< per corner 3f+k: u·w of its two edge vectors (|u||w| cos θ)
  std::vector<double> cornerCot;     ///< per corner, clamped to ±1e3; 0 in degenerate faces
  std::vector<double> cornerArea;    ///< per corner: the part of its face's area given to its vertex
  std::vector<double> edgeLength;    ///< per edge
  std::vector<double> edgeWeight;    ///< per edge: C_ij = ½(cot α_ij + cot β_ij)
  std::vector<double> vertexArea;    ///< per vertex: A_i (mixed or barycentric)
  std::vector<double> ringArea;      ///< per vertex: Σ of the incident faces' areas
  std::vector<Vec3> vertexNormal;    ///< per vertex: area-weighted, unit (zero if undefined)
  std::vector<double> angleSum;      ///< per vertex: Σ of incident corner angles
  DegeneracyCounts degenerate;

  /// True when vertex i has a usable area and normal (not isolated, not degenerate).
  bool isRegular(int i) const { return vertexArea[i] > 0; }
  /// The angle at corner c, radians (computed on demand: a step needs only the sums).
  double cornerAngle(std::size_t c) const;
};

/// Fills `g` (reusing its storage: no allocation once sized) from positions `p`.
/// `p.size()` must equal `topo.vertexCount()`. With `active` (one flag per vertex), the per-vertex
/// quantities (areas, normals, angle sums) are computed at the flagged vertices only and are zero
/// elsewhere, and `g.degenerate` counts flagged vertices only; faces and edges are all computed.
/// With `kept`, `g` already holds this function's values (same `areaType`) for the faces and
/// edges it flags, at positions `p`; a flow's fixed faces around a moving region are most of its
/// mesh.
struct GeometryKept {
  /// One flag per face: the same corners as when `g` was computed, none of them moved. A flagged
  /// face that was and stays non-degenerate keeps its values (they do not depend on the floors).
  const std::vector<std::uint8_t>* faces = nullptr;
  /// One flag per edge of `topo`, which `g` was computed for: neither end moved. Keeps its length.
  const std::vector<std::uint8_t>* edges = nullptr;
};
/// `floorScale` > 0: the length the degeneracy floors are relative to, and g.meanEdgeLength, instead
/// of topo's mean edge (a piece of a mesh measured as the whole is: the whole's mean edge length).
void computeGeometry(const Topology& topo, const std::vector<Vec3>& p, VertexArea areaType, Geometry& g,
                     const std::vector<std::uint8_t>* active = nullptr, const GeometryKept& kept = {},
                     double floorScale = 0);

/// Convenience overload returning a fresh cache.
Geometry computeGeometry(const Topology& topo, const std::vector<Vec3>& p,
                         VertexArea areaType = VertexArea::Mixed);

/// Mean edge length of a mesh (0 for a mesh without edges).
double meanEdgeLength(const Topology& topo, const std::vector<Vec3>& p);

/// The diagonal of the axis-aligned box around `p` (every point, as MeshLab's bbox): the length
/// that sizes given as a fraction (FlowOptions::featureSize at the faces) are fractions of.
double boundingBoxDiagonal(const std::vector<Vec3>& p);

}  // namespace elastica
