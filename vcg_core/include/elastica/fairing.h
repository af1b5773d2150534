// SPDX-License-Identifier: GPL-3.0-or-later
// Fairing a mesh with a flow: the coarse-to-fine schedule (flow to near steady state, 1-to-4
// subdivision, flow again), the stopping rules and the safety net.
#pragma once

#include <elastica/face_set.h>
#include <elastica/flow.h>
#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Fairs the whole of `mesh` in place with `opt.flow`, coarse to fine if opt.subdivisionLevels > 0.
///
/// Input: a triangle mesh with manifold edges and consistently oriented faces (what the readers
/// of elastica::io guarantee). Vertices on the boundary and their one-ring neighbours stay fixed
/// bit for bit with BoundaryMode::Fixed (two rows, for G¹ continuity); with BoundaryMode::Slide
/// the boundary vertices move along the boundary curve. Without subdivision, edge flips and
/// remeshing the faces stay as they are; with them, the mesh is rebuilt (new vertices and faces
/// appended, flipped faces renumbered in place). Remeshing (FlowOptions::remesh, the semi-implicit
/// scheme's default) rewrites only faces whose three vertices move: vertices that do not move keep
/// their position and their order, and their index unless the region lost more vertices than it
/// gained and one would fall past the end; faces touching one keep those vertices (renumbered
/// with them; a moving corner moves, or is joined to a neighbour) and their order, and their index
/// unless the region lost more faces than it gained and too few remain to fill the slots before
/// the last of them (a border, remeshed coarse). The
/// semi-implicit scheme with remeshing never returns crossing faces when the input had none.
/// FlowReport::energyInitial is the energy where the first flow starts (after any subdivision
/// made before it).
///
/// Stops at the energy plateau (FlowOptions::energyTolerance in both schemes; plateauTolerance and
/// shapeTolerance in the semi-implicit one as well), at maxSteps / maxSeconds, or
/// when the progress callback cancels; FlowReport::stop says which.
///
/// @throws InvalidInputError if the options are invalid, nothing can move, or a sliver would make
///         the explicit step vanish; the mesh is then unchanged.
/// @throws FlowDivergedError (a NumericalError, carrying the report so far) if the flow diverges
///         (non-finite positions, an energy blow-up, the mesh size running away); the mesh is then
///         left in the last good state checked (at most checkInterval steps back).
FlowReport fair(TriMesh& mesh, const FlowOptions& opt = {});

/// Fairs only `region` of `mesh`: the vertices whose faces all lie in the region move; every
/// other vertex keeps its position bit for bit (and, with a fixed boundary, so do the region's
/// two outer rows, as if the region's border were the mesh's boundary). With subdivision only the
/// region is refined 1-to-4 (its children form the region), and the faces that share an edge with
/// it are split to keep the mesh conforming (subdivideMidpointRegion); every other face keeps its
/// index and vertices. FlowReport::regionFaces lists the region's faces in the output mesh.
///
/// The run works on a piece of the mesh: the region's faces, the three rings of faces around it
/// (its fixed rings and what their operators read) and the faces of the rest that come near it
/// (within a quarter of its box's diagonal), as fixed obstacles. Time and memory of the flow and
/// of the checks below scale with the piece, not with the mesh (a few linear passes over the faces
/// remain: the selection flags, the vertex→face index, the obstacle search). The result is written
/// back in this order: every vertex that does not move keeps its index; the region's surviving and
/// new vertices fill the slots of the vertices that moved, ascending, then are appended; faces off
/// the region keep their index and value; the region's faces fill its slots, ascending, then are
/// appended. If the region comes back with fewer vertices (or faces) than it had, the slots left
/// over are removed and the vertices (faces) after them move down, keeping their order. The whole
/// mesh is never flowed: if nothing the piece's run reached passes the checks below, the input
/// comes back (StopReason::Unchanged).
///
/// The output is checked against the input before it is returned: a manifold mesh (nothing
/// beyond the input's own defects), no two vertices of the region's faces or their neighbours at
/// one point and no more faces crossing there (against the region's piece, and against every face
/// of the mesh near the result if it left the piece's box) than in the input, every face off the region as it
/// was bit for bit, and the region's energy (FlowReport::regionEnergyBefore / After: its faces'
/// vertices, each mesh at its own resolution) not above its start. An output that fails is not
/// returned (FlowReport::refusedBecause says what failed): the last stage end of the schedule that
/// passed comes back instead (FlowReport::keptStage), or if none did, the mesh unchanged with
/// StopReason::Unchanged. A time or step limit keeps the state reached if it passes.
///
/// @throws InvalidInputError as the whole-mesh fair(), and if an index of `region` is not a face
///         of `mesh` or the region leaves no vertex free to move; the mesh is then unchanged.
/// @throws FlowDivergedError as the whole-mesh fair(), but the mesh is then the last stage end that
///         passed the checks, or the input.
FlowReport fair(TriMesh& mesh, const FaceSet& region, const FlowOptions& opt = {});

}  // namespace elastica
