// SPDX-License-Identifier: GPL-3.0-or-later
// Keeping the triangles fit for the discrete operators while a flow runs: the paper's future work
// (dynamic connectivity, its ref. [7]) as stages of the semi-implicit pipeline. Measured on coarse
// polygon cages (docs/figures.md, "Cages from elsewhere"):
//  - a flow on a few dozen vertices is meaningless: the discrete energy of such a mesh is far below
//    the continuum's, and what the flow learns there (a handle pinched to a thin neck) is locked in
//    by subdivision. A 5×5 quad torus flowed from 25 vertices ended as a pinched torus (E 100);
//    subdivided twice before its first flow it reaches the Clifford torus (E 78.7, 8π² = 79.0);
//  - long thin triangles (quads split along one diagonal, CAD slivers) break the cotangent
//    operators: genus-2 and genus-3 block cages self-intersected (E 312 and 436); remeshed to even
//    triangles they reach 112–113 and 142 (the genus-2 minimiser has about 112.8).
#pragma once

#include <elastica/flow.h>
#include <elastica/topology.h>
#include <elastica/types.h>
#include "flow/moving_region.h"

#include <cstdint>
#include <vector>

namespace elastica {

/// The genus of a closed mesh, from its Euler characteristic; 0 for a mesh with a border (a region
/// with a border counts as a disk).
int closedGenus(const Topology& topo);

/// Free vertices the first flow stage wants: 100, plus 1,000 per handle (the genus from the Euler
/// characteristic of a closed mesh; a region with a border counts as a disk). Below it, the
/// schedule subdivides before flowing, within the levels the caller asked for. A flow on a few dozen
/// vertices is meaningless; on a handle resolved by a few hundred, a thin tube pinches: a 96-vertex
/// ring cage (R/r 10) flowed coarse to fine from 283 vertices reached E 38–63 < 8π² ≈ 79 (vector
/// and semi-implicit schemes alike), and at --subdivide 2 the curvature-adaptive remeshing of the
/// pinch ended at E 3,824 with crossing faces; subdivided first (1,536 and 6,144 vertices) it
/// converged at E 78.6 and 78.9. The floor was 100 per handle plus 100 before.
int workingResolutionFloor(const MovingRegion& region);

/// One level of the coarse-to-fine refinement: the whole mesh 1-to-4 (no selection), or only
/// the selected faces, their neighbours split to stay conforming (subdivideMidpointRegion; the
/// selection follows).
void subdivideOneLevel(MovingRegion& region);

/// Subdivides the region's mesh (subdivideOneLevel) while fewer than workingResolutionFloor()
/// vertices move, at most opt.subdivisionLevels times and not below opt.targetEdgeLength.
/// Returns the number of subdivisions made: the levels the schedule has used up.
int subdivideToWorkingResolution(MovingRegion& region, const FlowOptions& opt);

/// A flowed mesh the discrete operators no longer serve and a remeshing can mend: an angle below
/// 20° among the moving faces (on a whole mesh with fixed vertices, those without a vertex next to
/// a fixed one: the remeshing keeps the edges along the fixed rows), or a moving vertex with
/// κℓ > 0.6 (largestMovingCurvatureTimesEdge).
bool needsRemeshing(const MovingRegion& region);

/// Smallest corner angle, in degrees, of the faces whose three vertices all move (180 if none).
double smallestMovingAngle(const MovingRegion& region);

/// The largest principal curvature |H| + √max(H² − K, 0) at each vertex of the region's mesh
/// (mixed areas: what measureCurvature() gives).
std::vector<double> largestPrincipalCurvature(const MovingRegion& region);

/// max over the `moving` vertices of κ·(mean length of the vertex's edges), κ = |H| + √max(H² − K, 0)
/// from the given curvatures (what largestMovingCurvatureTimesEdge measures, on a flow's own caches).
double largestCurvatureTimesEdge(const Topology& topo, const std::vector<Vec3>& positions, const std::vector<double>& H,
                                 const std::vector<double>& K, const std::vector<std::uint8_t>& moving);

/// max over moving vertices of κ · (mean length of its edges): above about 0.6 the discrete energy
/// no longer sees what bending there costs (a neck can pinch for free).
double largestMovingCurvatureTimesEdge(const MovingRegion& region);

/// Isotropic remeshing (split, collapse, flip, tangential relaxation: mesh/patch_remeshing.h)
/// of the faces whose three vertices all move, toward the edge length of an equilateral triangle
/// of the region's mean face area (so the vertex count stays about the same) or, with
/// `curvatureAdaptive`, toward 0.4/κ where that is shorter (κ the largest principal curvature
/// around the vertex; at most 8× shorter): a flowed surface's necks get the edges that let the
/// energy see them. Not for an unflowed cage, whose curvature sits in its creases. Vertices that do not
/// move, and every face touching one, keep their positions and values bit for bit; vertices are
/// renumbered only where movable ones were removed. The selection (if any) follows the faces. The
/// remeshing is undone, and false returned, if it would make faces cross that did not cross before
/// (mesh/self_intersection.h), or if the region's deadline (MovingRegion::deadline) passed before
/// it ended, as for splitLongEdges and remeshOnSurface. `coarsening` multiplies the target edge length (a coarse start,
/// coarseStart: 2^k for k levels). `maxMoving` (0: none) bounds the moving vertices the
/// remeshing leaves (vertexBudget): where the curvature-adaptive edges would need more, the
/// shortest targets are raised to a common floor until the predicted count fits, so the necks stay
/// the most refined places, and splitting stops at the bound. `refineAt` (one flag per vertex, or
/// null) asks for edges half as long as they are now around the flagged vertices, below the
/// curvature's target: where a Loop subdivision showed that the mesh does not resolve its shape
/// (flow/resolution_check.h).
/// `crossingRefinements` (0: none) tries again that many times where a whole-mesh remeshing made
/// faces cross, with the targets halved around the crossing faces each time: two sheets closer than
/// the edge length (femur: a tunnel 0.4 target edges wide) need edges of their gap there.
/// `onSurface` keeps every vertex on the region's surface as it is (PatchRemeshingOptions::surface,
/// without sharp edges): a remeshing that resamples the surface and never moves it, for a part
/// whose thin walls every other remeshing put through each other (remeshOnSurface).
bool remeshMovingRegion(MovingRegion& region, bool curvatureAdaptive, double coarsening = 1, long long maxMoving = 0,
                        const std::vector<std::uint8_t>* refineAt = nullptr, int crossingRefinements = 0,
                        bool onSurface = false);

/// A CAD tessellation's long thin triangles, split toward the edge length of remeshMovingRegion's
/// isotropic target (moving faces only, one pass without relaxation): no input vertex moves and
/// new ones are made on its edges, so the surface changes only where the remesher's flips and
/// collapses of new vertices re-form faces that turn little. The relaxation of an isotropic
/// remeshing slides vertices over slivers a long way and can make faces cross (joint, a genus-2
/// part of 221 vertices with corners under 0.5°; a washer of aspect-40 strips), and the remeshing
/// is then refused; after the split its moves are short. False, with the region as it was, if
/// nothing was split, an edge is a vertex thrown far away, the split would pass its bound (64×
/// the vertices + 2,000), or the split made faces cross.
bool splitLongEdges(MovingRegion& region);

/// A CAD tessellation remeshed on its own surface toward edges of length `edge` (remeshRegion with
/// PatchRemeshingOptions::surface: every vertex stays on the input's faces, its sharp edges, those
/// whose faces' normals differ by more than kSharpEdgeDegrees, stay, and no collapse or flip crosses
/// one): the part is not moved, only its triangulation. For thin walls whose every other remeshing
/// makes faces cross (rotor, anchor: their relaxation or collapses put one side through the other).
/// Whole closed meshes only. False, with the region as it was, on a selection or a mesh with a
/// border, if the remeshing made faces cross where none crossed, stacked vertices or left no vertex.
bool remeshOnSurface(MovingRegion& region, double edge);

/// The edge length of a CAD tessellation's working resolution (issue 40 item 3): a few edges
/// (kEdgesAcrossThinnest) across the part's thinnest feature (thinnestFeature, mesh/thickness.h:
/// a low quantile of the local thickness), so the flow moves the part, not its triangulation; no
/// shorter than the edge of an equilateral remeshing of the moving area into vertexBudget(moving
/// vertices, genus) vertices. 0 (no such size) on a mesh with a boundary or a selection, or whose
/// thickness cannot be measured.
double cadWorkingEdgeLength(const MovingRegion& region);

/// The edge length remeshMovingRegion aims at with `coarsening` 1: an equilateral triangle of the
/// moving faces' median area.
double isotropicTargetEdge(const MovingRegion& region);

/// Whether the isotropic remeshing's edge (isotropicTargetEdge) is more than
/// kIsotropicOverThinnest times the part's thinnest feature (thinnestFeature, as
/// cadWorkingEdgeLength measures it): a remeshing at that size would fold the part's thin walls
/// into a mesh that cannot resolve them. False on a mesh with a boundary or a selection, or whose
/// thickness cannot be measured.
bool isotropicEdgeMissesThinnest(const MovingRegion& region);

/// The moving vertices a flow of genus `genus` needs at the current level: those it has now
/// (`moving`) plus what curvature-adaptive remeshing of a fair shape adds. Edges of 0.4/κ put
/// κ²/(0.4² · √3/2) ≈ 7.2 κ² vertices on a unit of area, and ∫κ² ≤ E, the energy, which a fair
/// shape of genus g keeps below 8π(g + 3) (the genus bound 32π + 8π(g − 1)); four times that, for
/// the one-ring maximum of κ that widens each refined place and the grading around it (twice that
/// would have bound the elephant's run: docs/decisions.md, "The remeshing's vertex budget"). Each later level
/// multiplies it by 4 (a 1-to-4 subdivision).
long long vertexBudget(long long moving, int genus);

/// A coarse start: the moving faces remeshed at 2^k times their edge length (a 4^k-th of their
/// vertices) and flowed there, then subdivided k times back to their resolution (subdivideLoop on a
/// closed mesh, subdivideMovingFaces on a mesh with a border), so that the many steps a shape change
/// takes run on the small mesh and the full-size one flows only the last few. A closed mesh keeps
/// kCoarseStartVertices or more at the coarse level (0 levels below 4 × that many), a mesh with a
/// border kCoarseStartBorderedVertices moving ones; a selection has none. With the levels: the
/// remeshing's target as a multiple of isotropicTargetEdge() (2^k on a closed mesh; on a mesh with a
/// border, 2^k times the edge of the moving faces' mean area over their median's), and whether the
/// refinement subdivides the moving faces only (subdivideMovingFaces: a border) or the whole mesh
/// (subdivideLoop).
struct CoarseStart {
  int levels = 0;
  double coarsening = 1;
  bool onMovingFaces = false;
};
CoarseStart coarseStart(const MovingRegion& region);

/// One level of a coarse start's refinement on a mesh with a border (or a selection): the faces whose
/// three vertices move, Loop-subdivided (subdivideLoopRegion); the faces around them that share an
/// edge with one are split to stay conforming, and no fixed vertex and no other face changes. The
/// selection (if any) follows: every split face was selected, and its children are.
void subdivideMovingFaces(MovingRegion& region);

}  // namespace elastica
