// SPDX-License-Identifier: GPL-3.0-or-later
// Refining a hole's triangulation until its triangles match the density of the mesh around it
// (Liepa, "Filling Holes in Meshes", SGP 2003, §4): split triangles at their centroids where they
// are too large for the edge lengths at their corners, keep the patch Delaunay by edge flips.
#pragma once

#include <elastica/hole_filling.h>
#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Refines the faces flagged in `patchFace` (one byte per face; new faces are appended flagged).
/// `sigma` holds the local edge length at each vertex (for the patch's border: the mean length of
/// its edges around the hole); split points get the mean of their corners' and are appended, on
/// the patch's triangles. Only edges between two patch faces are flipped, never to an edge that
/// already exists, so the border and everything outside the patch stay as they are.
void refinePatch(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma,
                 const PatchRefinementOptions& opt = {});

/// Lowers the `sigma` of each vertex on the patch's border (a corner of an edge with one patch
/// face) to the mean length of its border edges where that is shorter, for a patch whose
/// refinement asked for no vertex inside: the mean length of all the mesh edges at a border
/// vertex reads long where the mesh's triangles are long across the border (CGAL's bull: border
/// edges of 0.008 against 0.014), and Liepa's rule then leaves a fan of needles. Returns true if
/// a `sigma` changed.
bool sizeBorderByItsOwnEdges(const TriMesh& mesh, const std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma);

}  // namespace elastica
