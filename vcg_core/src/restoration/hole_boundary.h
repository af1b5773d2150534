// SPDX-License-Identifier: GPL-3.0-or-later
// The holes of a mesh: its boundary loops, walked in the direction a filling patch must take so
// that the new faces are oriented like the old ones.
#pragma once

#include <elastica/topology.h>
#include <elastica/vertex_faces.h>

#include <functional>
#include <limits>
#include <vector>

namespace elastica {

/// One boundary loop. `vertices[i] → vertices[i+1]` (cyclically) is the direction of the *hole*:
/// the mesh face on that edge traverses it the other way. `outside[i]` is the third vertex of that
/// mesh face (its tangent plane is what a patch continues).
struct HoleLoop {
  std::vector<int> vertices;
  std::vector<int> outside;
  /// The loop passes through a vertex more than once (two holes touching at a vertex, or a hole
  /// pinched by a non-manifold vertex): not fillable as one disc.
  bool pinched = false;
  int edgeCount() const { return static_cast<int>(vertices.size()); }
};

/// One edge of a hole, in the hole's direction: the mesh face on it is (to, from, outside).
struct HoleHalfEdge {
  int from, to, outside;
};

/// All boundary loops of a mesh, each starting at its smallest boundary half-edge (deterministic).
std::vector<HoleLoop> findHoleLoops(const Topology& topo);
/// The same from the mesh's boundary half-edges alone (in any order): time and memory in
/// proportion to the holes' borders.
std::vector<HoleLoop> findHoleLoops(std::vector<HoleHalfEdge> edges);

/// The boundary half-edges of `mesh`, whose faces around each vertex `adjacency` lists, in one pass
/// over the faces and without arrays of the mesh's size (a whole-mesh Topology of a scan of
/// millions of vertices takes several times the mesh's memory).
/// @throws InvalidInputError on an edge shared by more than two faces (the message names it).
std::vector<HoleHalfEdge> boundaryHalfEdges(const TriMesh& mesh, const VertexFaces& adjacency);

/// @throws InvalidInputError if a face of `mesh` uses a vertex outside [0, vertexCount()) or
///         repeats a vertex (the message names the face): what boundaryHalfEdges needs.
void checkFaceIndices(const TriMesh& mesh);

/// The unit area vector (Newell's normal) of the closed polygon through `vertices`, or zero if the
/// polygon has no area seen from any side (a tube's cut, a loop folded onto itself).
Vec3 polygonNormal(const std::vector<Vec3>& positions, const std::vector<int>& vertices);

/// The winding number of the closed polygon through `vertices` around `p`, both seen along
/// `normal` (a unit vector): ±1 inside a simple polygon, 0 outside.
double windingNumber(const std::vector<Vec3>& positions, const std::vector<int>& vertices, const Vec3& normal, const Vec3& p);

/// Islands: for each loop, the index of the loop in whose hole it lies as the border of an island
/// (a separate piece of the mesh whose only border it is, as a scanner leaves a fragment floating in
/// a gap: inside the hole's outline seen along the hole's mean normal, and nearer the hole than the
/// hole is wide), or -1. A disc patch across such a hole would cross the island, and one across
/// the island's own border would close the island onto itself. Costs in proportion to the loops
/// and to the islands' faces.
std::vector<int> islandsInHoles(const TriMesh& mesh, const VertexFaces& adjacency, const std::vector<HoleLoop>& loops);

/// The angle, in radians, that `faces` (the faces around `v`, in `mesh`) span at `v`: the sum of
/// their corner angles there.
double cornerAngleSum(const TriMesh& mesh, VertexFaces::FaceRange faces, int v);

/// The largest smallest angle (radians) that patch faces at a border corner can have, in the
/// corner's plane: the corner's angle `theta` lies between border edges of lengths `a` and `b`, and
/// the faces there either hold it whole (the ear on both edges, whose other angles follow from a,
/// b and theta: 11.7° for a 39° corner between edges of 1 and 3.8), split it between two faces
/// sharing an apex (the best apex, searched), or split it among three or more (theta/3 at most).
/// At most theta; theta itself for a corner below 60° between edges of equal length.
/// `enough`: the search ends as soon as the bound is known to be at least this, and returns a
/// value at least this (for a minimum over corners: a corner that cannot lower it).
double cornerBound(double a, double b, double theta, double enough = std::numeric_limits<double>::infinity());

/// The smallest angle any patch of `loop` can have, in degrees, as far as its border decides: the
/// smallest cornerBound() over the corners that the hole's side sees as convex (the mesh's own
/// faces there span more than 180°). 180 when no corner is convex.
/// `meshAngle(v)`: the angle the mesh's own faces span at v, in radians (cornerAngleSum).
double borderCornerBoundDegrees(const std::vector<Vec3>& positions, const HoleLoop& loop,
                                const std::function<double(int)>& meshAngle);

}  // namespace elastica
