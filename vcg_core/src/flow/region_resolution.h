// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a region's result resolves the surface it stands for (issue 42). The vector scheme moves
// vertices along the surface as freely as across it, and on a region clamped at its rim it can
// lower the discrete energy by moving them out of the region's middle: a few large flat faces
// meeting at creases, whose discrete energy is small (a crease's vertices have large areas) while
// the surface they stand for is a faceted lid (docs/decisions.md, "Regions": resolved regions). Loop's
// limit surface is smooth: where the mesh resolves its shape E changes little under one
// subdivision, where it does not the creases show what they cost. resolution_check.h measures
// the same for whole closed meshes.
#pragma once

#include <elastica/flow.h>
#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// A region's energy over its moving vertices, beside the same part of its Loop subdivision.
struct RegionResolution {
  /// Σ (4H² − 2K) A over the region's inner vertices (every face of theirs in the region, none on
  /// a border of the mesh): the vertices the flow moves.
  double energy = 0;
  /// The same over the region Loop-subdivided once (the region's border and the rest of the mesh
  /// stay): its inner vertices as they move under Loop's masks, and the new vertices of the edges
  /// between two of them, which cover the same part of the surface.
  double loopEnergy = 0;
  /// (loopEnergy − energy) / max(|energy|, 1).
  double gap() const;
  /// gap() at most kRegionResolvedGap (flow.h).
  bool resolved() const;
  /// The larger of the two: what the region's surface costs whichever way its mesh errs (a faceted
  /// lid under-counts at its own resolution, a rough surface that Loop smooths over-counts there).
  double resolvedEnergy() const { return loopEnergy > energy ? loopEnergy : energy; }
};

/// Measures the region of `mesh` flagged in `selection` (one byte per face) with `opt`'s vertex
/// areas and curvature. A region with no inner vertex measures 0 and 0 (resolved).
/// @throws InvalidInputError as Topology on a non-manifold region.
RegionResolution measureRegionResolution(const TriMesh& mesh, const std::vector<std::uint8_t>& selection,
                                         const FlowOptions& opt);

}  // namespace elastica
