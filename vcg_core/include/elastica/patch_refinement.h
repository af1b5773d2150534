// Refining a hole's triangulation until its triangles match the density of the mesh around it
// (Liepa, "Filling Holes in Meshes", SGP 2003, §4): split triangles at their centroids where they
// are too large for the edge lengths at their corners, keep the patch Delaunay by edge flips.
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

struct PatchRefinementOptions {
  /// Liepa's density factor α: a triangle is split when α times each centroid–corner distance
  /// exceeds the local edge length at the corner and at the centroid. √2 gives triangles about as
  /// large as the surrounding ones.
  double density = 1.4142135623730951;
  int maxPasses = 64;  ///< split passes (each roughly triples the triangles that still need it)
};

/// Refines the faces flagged in `patchFace` (one byte per face; new faces are appended flagged).
/// `sigma` holds the local edge length at each vertex (for the patch's border: the mean length of
/// its edges around the hole); split points get the mean of their corners' and are appended, on
/// the patch's triangles. Only edges between two patch faces are flipped, never to an edge that
/// already exists, so the border and everything outside the patch stay as they are.
void refinePatch(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma,
                 const PatchRefinementOptions& opt = {});

}  // namespace elastica
