// SPDX-License-Identifier: GPL-3.0-or-later
// The curvature of a mesh in one call: per-vertex mean and Gaussian curvature and the total
// curvature energy, for users and reports. (The flows use the cached operators of curvature.h.)
#pragma once

#include <elastica/curvature.h>
#include <elastica/geometry.h>
#include <elastica/topology.h>
#include <elastica/types.h>

#include <cstddef>
#include <vector>

namespace elastica {

struct CurvatureMeasureOptions {
  VertexArea area = VertexArea::Mixed;  ///< Meyer et al.'s mixed area, or the paper's A/3
  CurvatureOptions curvature;           ///< with H2KTreatment::PaperLambda, Hlambda is filled
};

struct MeshCurvature {
  /// Mean curvature per vertex in the reported sign (sign_convention.h): +1/r on a sphere with
  /// outward normals. 0 where a vertex has no usable area.
  std::vector<double> H;
  /// With the paper's λ rule: H/λ on the vertices it rescales, H elsewhere (reported sign);
  /// empty otherwise.
  std::vector<double> Hlambda;
  std::vector<double> K;  ///< angle-deficit Gaussian curvature (2π − Σφ)/A; (π − Σφ)/A at the boundary
  /// Total curvature energy E = Σ (4H² − 2K) A over interior regular vertices (energy.h), raw H.
  double energy = 0;
  double lambda = 1;                ///< the paper's λ (1 without the λ rule)
  std::size_t lambdaVertices = 0;   ///< vertices the λ rule rescaled
  DegeneracyCounts degenerate;      ///< faces, edges and vertices given zero weight
  int eulerCharacteristic = 0;
  std::size_t boundaryEdges = 0;
};

/// Measures `mesh`: nothing is changed. Input: a triangle mesh with manifold edges.
/// Degenerate elements (zero-area faces, zero-length edges, isolated vertices) get zero weight and
/// are counted in MeshCurvature::degenerate; they never make a value non-finite.
/// @throws InvalidInputError on a non-manifold edge, a face index out of range or a face that
///         repeats a vertex.
MeshCurvature measureCurvature(const TriMesh& mesh, const CurvatureMeasureOptions& opt = {});

/// measureCurvature() on the caller's Topology of `mesh` (Topology(mesh.vertexCount(), mesh.faces)),
/// for a caller that has built it already (an input check): the same values.
MeshCurvature measureCurvature(const Topology& topo, const TriMesh& mesh, const CurvatureMeasureOptions& opt = {});

/// The total curvature energy of `after` minus that of `before`, measured only where they differ:
/// on the vertices whose fan differs (a face of it missing from the other mesh, or a vertex of it at
/// another position or index), each on its faces. For a mesh that changed in a small region (a
/// region's fair: faces off it keep their index and value) this costs a few linear passes over the
/// faces instead of two whole measures. measureCurvature(after).energy − measureCurvature(before).energy
/// up to the order of the sums (and a face degenerate to 1e-12 of the edge length, whose threshold
/// follows the measured part's mean edge length, as measureCurvatureInPieces()). With the paper's λ
/// rule (global) it is that difference, measured whole.
/// @throws InvalidInputError as measureCurvature().
double curvatureEnergyChange(const TriMesh& before, const TriMesh& after, const CurvatureMeasureOptions& opt = {});

/// What an input check rejects beyond Topology's throws, as Topology counts them:
/// measureCurvatureInPieces() counts them on the way (each edge and vertex in one piece), so an
/// input check and a whole-mesh energy need no whole-mesh Topology.
struct MeshDefects {
  int inconsistentEdges = 0;    ///< Topology::inconsistentEdgeCount()
  int nonManifoldVertices = 0;  ///< Topology::nonManifoldVertexCount()
};

/// measureCurvature() a piece at a time, for large meshes: the vertices in blocks of
/// `pieceVertices`, each measured on the faces around it, so that the memory beyond the mesh and
/// the result follows a piece, not the mesh (a whole-mesh Topology, Geometry and Curvature of a
/// 2.2-million-vertex scan took 1.1 GB, ten times the mesh's bytes). H and K are
/// measureCurvature()'s (each vertex has its whole fan, listed in the same order), but for faces
/// degenerate to 1e-12 of the edge length (the threshold follows each piece's mean edge length);
/// the energy is summed piece by piece; eulerCharacteristic, boundaryEdges and the degenerate
/// counts count each edge and face once (degenerate at the piece's mean edge length). The paper's λ
/// rule (opt.curvature.h2k = PaperLambda) needs the whole mesh, and a mesh of at most
/// `pieceVertices` vertices is one piece: both are measureCurvature().
/// With `defects`, also counts them (as Topology, whole, would).
/// @throws InvalidInputError as measureCurvature() (a face that repeats a vertex or a non-manifold
///         edge is named in the piece's numbers).
MeshCurvature measureCurvatureInPieces(const TriMesh& mesh, const CurvatureMeasureOptions& opt = {},
                                       int pieceVertices = 1 << 17, MeshDefects* defects = nullptr);

}  // namespace elastica
