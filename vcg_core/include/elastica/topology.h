// SPDX-License-Identifier: GPL-3.0-or-later
// Connectivity of a triangle mesh in compact arrays (CSR), built once per connectivity change
// (start, subdivision, remeshing). Every per-step operator reads it and allocates nothing.
#pragma once

#include <elastica/types.h>
#include <elastica/vertex_faces.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace elastica {

/// Corner c = 3·f + k is vertex faces[f][k] of face f; the edge opposite corner k joins
/// faces[f][k+1] and faces[f][k+2] (indices mod 3).
class Topology {
 public:
  /// Builds the adjacency of `faces` over `vertexCount` vertices.
  /// @throws InvalidInputError on an index out of range, a face that repeats a vertex, or an edge
  ///         shared by more than two faces (non-manifold edge). The message names the face/edge.
  Topology(int vertexCount, const std::vector<Face>& faces);
  /// An empty topology (no vertices, no faces), to rebuild() later.
  Topology() = default;

  /// Builds the adjacency of `faces` anew, as the constructor does, reusing this object's storage
  /// (a loop over pieces of a mesh then allocates nothing once the arrays are large enough).
  /// @throws InvalidInputError as the constructor; the topology is then empty.
  void rebuild(int vertexCount, const std::vector<Face>& faces);

  /// The most vertices of any Topology built in this process since the last reset: tests check
  /// with it that a path works on pieces of a mesh and never builds the whole mesh's.
  static int largestBuilt();
  static void resetLargestBuilt();

  int vertexCount() const { return nv_; }
  int faceCount() const { return static_cast<int>(faces_.size()); }
  int edgeCount() const { return static_cast<int>(edgeVertices_.size()); }
  const std::vector<Face>& faces() const { return faces_; }

  /// Endpoints of edge e (smaller index first).
  const std::array<int, 2>& edgeVertices(int e) const { return edgeVertices_[e]; }
  /// Corners opposite edge e in its (one or two) faces; -1 where there is no second face.
  const std::array<int, 2>& edgeOppositeCorners(int e) const { return edgeCorners_[e]; }
  bool isBoundaryEdge(int e) const { return edgeCorners_[e][1] < 0; }

  /// One-ring of vertex v: neighbours [ringBegin(v), ringEnd(v)) in ringVertex()/ringEdge().
  int ringBegin(int v) const { return ringOffset_[v]; }
  int ringEnd(int v) const { return ringOffset_[v + 1]; }
  int ringVertex(int k) const { return ringVertex_[k]; }
  int ringEdge(int k) const { return ringEdge_[k]; }
  int valence(int v) const { return ringOffset_[v + 1] - ringOffset_[v]; }

  /// Corners of vertex v: [cornerBegin(v), cornerEnd(v)) in corner().
  int cornerBegin(int v) const { return corners_.offset(v); }
  int cornerEnd(int v) const { return corners_.offset(v + 1); }
  int corner(int k) const { return corners_.corner(k); }

  /// A vertex on a boundary edge. Boundary vertices carry no interior curvature: the energy skips
  /// them and the flows keep them fixed (or slide them) by constraint.
  bool isBoundaryVertex(int v) const { return boundaryVertex_[v] != 0; }
  /// A vertex referenced by no face.
  bool isIsolatedVertex(int v) const { return cornerEnd(v) == cornerBegin(v); }

  int boundaryEdgeCount() const { return boundaryEdges_; }
  /// Interior edges whose two faces traverse them in the same direction (inconsistent orientation).
  int inconsistentEdgeCount() const { return inconsistentEdges_; }
  /// Vertices whose incident faces form more than one fan (non-manifold "bow-tie" vertices).
  /// Counted on each call, in linear time: only input checks ask, and the flows, which rebuild the
  /// topology at every connectivity change, would otherwise pay for it at each build.
  /// With `only` (one flag per vertex), the flagged vertices alone are counted: a piece of a mesh
  /// that holds their whole fans but not every other vertex's.
  int nonManifoldVertexCount(const std::vector<std::uint8_t>* only = nullptr) const;
  /// Interior edge e's two faces traverse it in the same direction (counted in inconsistentEdgeCount()).
  bool isInconsistentEdge(int e) const;
  /// Bytes of the adjacency arrays (faces, edges, rings, corners, boundary flags).
  std::size_t byteSize() const;

  /// V − E + F.
  int eulerCharacteristic() const { return nv_ - edgeCount() + faceCount(); }

 private:
  void build(int vertexCount, const std::vector<Face>& faces);

  int nv_ = 0;
  std::vector<Face> faces_;
  std::vector<std::array<int, 2>> edgeVertices_;
  std::vector<std::array<int, 2>> edgeCorners_;
  std::vector<int> ringOffset_, ringVertex_, ringEdge_;
  VertexFaces corners_;
  std::vector<std::uint8_t> boundaryVertex_;
  int boundaryEdges_ = 0;
  int inconsistentEdges_ = 0;
};

}  // namespace elastica
