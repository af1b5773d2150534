// SPDX-License-Identifier: GPL-3.0-or-later
// Shape restoration (paper §4, Figs. 9–10): fill the holes of a mesh with patches that continue
// the surrounding surface's curvature. Each hole is triangulated (Liepa's minimum-weight
// triangulation), refined to the density around it, started from a bi-Laplace solve, and faired
// with a curvature flow while two rings of the surrounding mesh stay fixed (G¹ continuity).
#pragma once

#include <elastica/flow.h>
#include <elastica/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace elastica {

/// Liepa's refinement of a hole's triangulation (restoration/patch_refinement.h).
struct PatchRefinementOptions {
  /// Liepa's density factor α: a triangle is split when α times each centroid–corner distance
  /// exceeds the local edge length at the corner and at the centroid. √2 gives triangles about as
  /// large as the surrounding ones.
  double density = 1.4142135623730951;
  int maxPasses = 64;  ///< split passes (each roughly triples the triangles that still need it)
};

/// Two copies of one point on a hole border: `removed` (the larger index) is welded into `kept`
/// (restoration/hole_pinches.h).
struct PinchWeld {
  int kept = -1, removed = -1;
};

/// How far the pipeline goes (each stage is a comparison in the restoration benchmark).
enum class FillStage {
  Triangulation,  ///< the minimum-weight triangulation only (no new vertices)
  Refinement,     ///< + refinement to the surrounding density (new vertices on the flat fill)
  Biharmonic,     ///< + the bi-Laplace solve (CGAL's fairing)
  Flow,           ///< + the curvature flow (default)
};

/// Options of fillHoles() (one line each: what, unit, default). The measurements behind the
/// defaults: docs/options.md.
struct HoleFillOptions {
  int maxHoleEdges = 500;  ///< holes with more border edges are left open (MeshLab's "Max size to be closed"); default 500
  /// Also close the outer rims of open surfaces (a loop that turns like an outline and spans a
  /// quarter or more of its piece's area; docs/restoration.md); default off: only holes are filled.
  bool closeRims = false;
  FillStage stopAfter = FillStage::Flow;  ///< the last stage of each hole's pipeline; default the flow
  PatchRefinementOptions refinement;      ///< Liepa's refinement of the triangulation
  /// Fair holes with at least this many border edges coarse to fine (border edges; 0: never):
  /// flowed at half the border's density first, then at its density along the border and 1/1.3 of
  /// it inside; default 700.
  int coarseFirstFromEdges = 700;
  /// The flow that fairs each patch (boundary mode ignored, no subdivision); default
  /// defaultFillFlow(): semi-implicit with edge flips, stopping once the patch's shape has settled.
  /// Its maxSteps and maxSeconds bound the whole fill (the holes' flows share them).
  FlowOptions flow = defaultFillFlow();

  static FlowOptions defaultFillFlow() {
    FlowOptions f;
    f.scheme = Scheme::SemiImplicit;
    f.flipEdges = true;
    f.shapeTolerance = 1e-3;
    f.remesh = false;  // the fill has its own refinement and remeshing stages, made for a patch
    return f;
  }
};

/// One stage of a hole's pipeline after its triangulation, measured on the same region as every
/// other (the patch's faces and their vertices, the border's included, each with its whole fan).
struct FillStageReport {
  /// "triangulation", "refinement", "bi-Laplace", "remeshing", "flow", "remeshing and flow"; coarse to
  /// fine (HoleFillOptions::coarseFirstFromEdges) also "coarse flow", "remeshing to the border's density"
  std::string stage;
  bool kept = false;   ///< false: the patch went back to what the last kept stage left
  double minAngleDegrees = 0;  ///< what the stage left, kept or not
  double energy = 0;           ///< total curvature energy of the region, kept or not
  long long steps = 0;         ///< flow steps the stage took
  double seconds = 0;          ///< wall time of the stage, its measuring included
  std::string why;             ///< why it was not kept ("smallest angle lower", "energy higher", an error)
};

/// What happened to one hole.
struct HoleReport {
  int borderEdges = 0;
  bool filled = false;
  /// The loop is an open surface's outer rim (HoleFillOptions::closeRims): left open unless asked.
  bool rim = false;
  std::string reason;        ///< why it was skipped, or what went wrong with the flow; empty if all went well
  int newVertices = 0, newFaces = 0;
  /// Total curvature energy of the patch's region (FillStageReport) at the bi-Laplace start …
  double energyBefore = 0;
  double energyAfter = 0;    ///< … and at the end (never higher: a stage that raises it is undone)
  long long steps = 0;
  StopReason stop = StopReason::Converged;
  double minAngleDegrees = 0;  ///< smallest angle in the patch's faces
  /// The smallest angle the border allows a patch (its sharpest convex corner inside the hole);
  /// the fill keeps every patch angle at or above min(25°, this) where it can.
  double borderBoundDegrees = 180;
  double seconds = 0;
  /// The stages run, in order, each kept only if it lowered neither the smallest angle (below
  /// min(25°, the last kept stage's)) nor raised the energy.
  std::vector<FillStageReport> stages;
};

struct HoleFillReport {
  std::vector<HoleReport> holes;
  /// Copies of one point on a hole border (a bow-tie vertex stored once per fan) merged into one
  /// vertex because a patch closed the gap between their fans, in the input's vertex numbers.
  /// The removed copies are gone from the output; the vertices after each move down by one.
  std::vector<PinchWeld> welds;
  /// The output's faces from this index on are new (patch faces); the ones before it are the
  /// input's, in their order.
  int firstNewFace = 0;
  bool isNewFace(int face) const { return face >= firstNewFace; }
  int filledCount() const;
  double seconds = 0;
};

/// Fills the holes of `mesh` with at most opt.maxHoleEdges border edges, in place.
///
/// Input: a triangle mesh with manifold edges (what the readers of elastica::io guarantee).
/// Original vertices and faces keep their order and values bit for bit, and new vertices and faces
/// are appended (HoleFillReport::firstNewFace), with one exception: a hole border that passes
/// twice through one point (two copies of a vertex, one per fan of faces) is split there into two
/// holes, and the copies become one vertex where a patch joins their fans
/// (HoleFillReport::welds). A mesh without holes is left as it is. A hole whose flow fails keeps
/// its bi-Laplace patch; its report says so. A hole with an island in it (a separate piece of the
/// mesh whose only border lies within the hole's outline, as scanners leave fragments in gaps) is
/// left open, and so is the island's border: a disc patch would cross the island, and one over the
/// island's border would close the island onto itself. Both reports say so; remove the fragment to
/// fill the hole.
///
/// Cost: the mesh is never copied. One pass over the faces finds the holes with a vertex→faces
/// index of a third of the mesh's bytes; each patch is made on a piece of the mesh around its hole,
/// and the patches are appended at the end, so the time beyond that pass and the memory beyond the
/// mesh follow the holes (200 holes in a 2.2-million-vertex scan: the fill's peak 1.9× the mesh's
/// bytes, 0.4 s outside the holes; bench/scan_holes_bench).
/// @throws InvalidInputError on non-manifold edges or invalid options; the mesh is then unchanged.
HoleFillReport fillHoles(TriMesh& mesh, const HoleFillOptions& opt = {});

/// What fillHoles accepts in a mesh but a caller may refuse before filling it.
struct FillInputDefects {
  int inconsistentEdges = 0;    ///< edges run the same way by both their faces (as Topology counts them)
  int nonManifoldVertices = 0;  ///< vertices where several fans of faces meet (as Topology counts them)
};

/// Counts them with a vertex→faces index (a third of the mesh's bytes) instead of a whole-mesh
/// Topology (several times the mesh): the check every face runs before fillHoles.
/// @throws InvalidInputError as fillHoles does: a face index out of range, a face that repeats a
///         vertex, an edge shared by more than two faces.
FillInputDefects countFillInputDefects(const TriMesh& mesh);

}  // namespace elastica
