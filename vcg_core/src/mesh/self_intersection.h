// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a mesh's faces cross each other: the flow's embedding guard. An output must never
// self-intersect when its input did not, and a handle that pinches shows up as faces crossing
// before it closes. Uniform-grid broad phase over the face boxes (linear in the face count for
// meshes of even triangles), exact-in-double segment–triangle tests for the narrow phase.
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Faces that cross another face, by vcglib's definition (Clean::SelfIntersections): faces
/// sharing no vertex cross if an edge of one passes through the interior of the other; faces
/// sharing one vertex s cross if the segment halfway between s and the opposite edge of one
/// passes through the other (one folded through the other around s); faces sharing an edge never
/// count. Touching and coplanar overlaps (measure zero for a flow) are not counted. With
/// `onlyFace` (one byte per face), pairs where neither face is flagged are skipped: the local test
/// after a step that moved only some faces. Returns the crossing faces' indices, ascending.
std::vector<int> selfIntersectingFaces(const TriMesh& mesh, const std::vector<std::uint8_t>* onlyFace = nullptr);

/// selfIntersectingFaces(mesh, onlyFace) is not empty; stops at the first crossing pair.
bool selfIntersects(const TriMesh& mesh, const std::vector<std::uint8_t>* onlyFace = nullptr);

/// The narrow phase of selfIntersectingFaces: faces `f` and `g` of `mesh` cross by the rule above.
bool facesCross(const TriMesh& mesh, const Face& f, const Face& g);

/// The narrow phase over a broad phase: `forEachPair(visit)` calls visit(f, g) for candidate
/// pairs (f < g) until visit returns true. The faces of the pairs that cross, ascending.
template <class ForEachPair>
std::vector<int> facesOfCrossingPairs(const TriMesh& mesh, ForEachPair forEachPair) {
  std::vector<std::uint8_t> hit(mesh.faces.size(), 0);
  forEachPair([&](int f, int g) {
    if (facesCross(mesh, mesh.faces[f], mesh.faces[g])) hit[f] = hit[g] = 1;
    return false;
  });
  std::vector<int> out;
  for (int f = 0; f < mesh.faceCount(); ++f)
    if (hit[f]) out.push_back(f);
  return out;
}

/// Whether a candidate pair of `forEachPair` (as above) crosses; stops at the first.
template <class ForEachPair>
bool anyPairCrosses(const TriMesh& mesh, ForEachPair forEachPair) {
  bool found = false;
  forEachPair([&](int f, int g) { return found = facesCross(mesh, mesh.faces[f], mesh.faces[g]); });
  return found;
}

/// A face whose box covers more grid cells than this (a CAD sliver's long side among small faces)
/// is tested against every face instead of being binned: the broad phases' common rule.
constexpr std::int64_t kMaxCellsPerFace = 512;

/// selfIntersects(after, &activeFace), for `after` made from `before` by rewriting some faces (edge
/// flips: the same positions and face count), where no pair with an active face crossed in `before`
/// (the flow's guard has just tested it) and the faces left as they were are flagged as they were
/// there. Then only a pair with a rewritten face can cross, and those pairs alone are tested: after
/// a step's flips, a handful of faces instead of the whole moving region. Where the positions or
/// the face count differ, or a rewritten face is not flagged, every pair with an active face is.
bool rewrittenFacesCross(const TriMesh& before, const TriMesh& after, const std::vector<std::uint8_t>& activeFace);

}  // namespace elastica
