// SPDX-License-Identifier: GPL-3.0-or-later
// Isotropic remeshing of a hole's patch (Botsch & Kobbelt, "A Remeshing Approach to
// Multiresolution Modeling", SGP 2004), restricted to the patch's faces: split long edges,
// collapse short ones, flip toward valence 6, relax tangentially. A deep hole's bi-Laplace patch
// is stretched unevenly (its vertices come from refining the flat fill); the flow moves vertices
// along their normals only, so the slivers it starts from are the slivers it ends with. The flow's
// quality stages remesh a moving region with it too (flow/mesh_quality_stage.h): it lives in the
// mesh tier, below both.
#pragma once

#include <elastica/types.h>

#include <chrono>
#include <cstdint>
#include <vector>

namespace elastica {

class SurfaceProjector;

struct PatchRemeshingOptions {
  /// Split–collapse–flip–relax rounds (Botsch & Kobbelt use 5–10). On 2,562-vertex spheres with
  /// polar caps of 40–120° cut away, 10 rounds of 10 passes left every restored patch's smallest
  /// angle at 22.6° or more (remeshing always kept); 5 rounds or 3 passes left single slivers (0.05–18°) on some caps.
  int iterations = 10;
  /// Tangential relaxation passes per round (Jacobi, each a full step to the neighbours' mean).
  int relaxPasses = 10;
  /// Splits stop once the mesh has this many vertices (0: no limit): a region whose edges span
  /// many orders of magnitude (a vertex thrown far away) would otherwise be split without end.
  int maxVertices = 0;
  /// Target edge lengths are this times `sigma` (a coarse pass over a patch whose sigma holds the
  /// border's density: restoration's coarse-to-fine fill). Sigmas of new vertices stay unscaled.
  double lengthScale = 1;
  /// Whether the region may end with fewer faces than it has slots before the last face outside it
  /// (remeshRegion). Off, collapses stop short of that and every face outside keeps its index; on,
  /// they do not, and the faces outside then keep their value and their order but move down (a
  /// mesh with a border, remeshed whole: its fixed rows' faces lie between the moving ones to the
  /// end of the face list, and nearly every collapse would be refused). Where the region still
  /// fills its slots the result is the same either way.
  bool regionMayShrink = false;
  /// The surface to keep the region on (null: none; mesh/surface_projection.h): a CAD
  /// tessellation's, whose remeshing must move its triangulation, not the part. With it, every
  /// vertex a split makes, a collapse places or the relaxation moves is put on its closest point of
  /// the surface (on a face turned its way), and a move the projection would carry farther than the
  /// move itself (onto another sheet) is dropped. The region's sharp edges (sharpEdges at the
  /// surface's feature angle, measured on the mesh handed over) stay: they are never flipped; a
  /// vertex on one sharp line moves and is placed along it only (projected onto the surface's sharp
  /// edges) and is collapsed only along it; a vertex where sharp lines meet or end never moves.
  const SurfaceProjector* surface = nullptr;
  /// No round starts once this time has passed (default: never): a flow's wall-time limit
  /// (FlowOptions::maxSeconds), which its remeshings would otherwise overrun by seconds before the
  /// flow could check it. The rounds done are kept; the caller judges the result (the flow's quality
  /// stages undo a remeshing that ends after the limit).
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

/// Remeshes the faces flagged in `patchFace` (one byte per face) toward the edge length `sigma`
/// (one per vertex; an edge's target is the mean of its ends'). Edges longer than 4/3 of their
/// target are split at their midpoint; edges shorter than 4/5 are collapsed (two new vertices meet
/// at the midpoint; a new vertex that close to an original one is joined to another of its new
/// neighbours instead); edges are flipped where that brings the valences of their four vertices
/// closer to 6; new vertices move toward the mean of their neighbours within their tangent plane.
///
/// What stays: vertices before `firstNew` never move and are never removed; edges with a face
/// outside the patch (the patch's border) are never split, collapsed or flipped; faces not flagged
/// keep their index and value. Collapses only join two new vertices, and only when the result is
/// still a manifold disk (link condition), no face turns over and no edge grows beyond 4/3 of its
/// target; relaxation steps that would turn a face over are halved or dropped.
/// What changes: new vertices (from `firstNew` on) are added, moved or removed, those that remain
/// renumbered in their order; the patch's faces are rewritten. Removed faces' slots are refilled
/// from the end of the face list, new faces appended flagged, so every slot before the last face
/// outside the patch still holds a patch face (a disk patch never has fewer faces than its border
/// has edges − 2, so a hole's triangulation slots stay filled too). `sigma` follows the vertices.
/// Lengths and tolerances are relative to `sigma`: scale-covariant.
void remeshPatch(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
                 const PatchRemeshingOptions& opt = {});

/// The general form, for any region of a mesh (the flow's moving region): vertices flagged in
/// `movable` (one byte per vertex; remeshPatch's "new" vertices) may move, be collapsed and be
/// removed, the others never; new vertices are movable. `movable` and `sigma` follow the
/// vertices. Every movable vertex should have a closed fan of region faces (a region's vertices
/// two rings inside its border have); the flow's moving region also hands over movable vertices
/// beside its fixed ones, whose faces outside the region then follow them (moved, or joined to a
/// neighbour by a collapse). Vertices not movable keep their index while the movable ones that
/// remain fill the slots before the last of them, and their order otherwise; faces not flagged keep
/// their corners that are not movable, and their index while the region fills its slots before the
/// last of them (always, unless PatchRemeshingOptions::regionMayShrink), and their order otherwise.
/// False if `opt.maxVertices` stopped a split pass (the region is remeshed all the same, with edges
/// left longer than their targets).
bool remeshRegion(TriMesh& mesh, std::vector<std::uint8_t>& regionFace, std::vector<double>& sigma,
                  std::vector<std::uint8_t>& movable, const PatchRemeshingOptions& opt = {});

}  // namespace elastica
