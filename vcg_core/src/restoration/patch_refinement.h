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

/// refinePatch, and again for a patch it gave no vertex inside whose smallest angle stays below
/// `needleDegrees` (sizeBorderByItsOwnEdges, patch_refinement.cpp, first sizes its border by the
/// border edges' own lengths): CGAL's bull, a 21-edge hole stayed a fan at 10.9° where the border
/// allows 22.5°.
void refinePatchOrItsFan(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma,
                         const PatchRefinementOptions& opt, double needleDegrees);

}  // namespace elastica
