// SPDX-License-Identifier: GPL-3.0-or-later
// The flow state's energy measured a piece of the mesh at a time: for a run whose own data is the
// peak meanwhile (the fairing amount's factor), so that the whole-mesh geometry and curvature are
// never held beside it.
#pragma once

#include <elastica/curvature.h>
#include <elastica/geometry.h>
#include <elastica/topology.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// totalCurvatureEnergy() of the active vertices, as FlowState computes it from computeGeometry()
/// and computeCurvature() on the whole of `topo` (with `active`), bit for bit: each vertex's energy
/// on the faces around it (its whole fan, listed in the mesh's order, the floors at the whole
/// mesh's mean edge length), then the same sum over the vertices. Pieces of `pieceVertices`
/// vertices, grown breadth first over the one-rings so that a piece's fans overlap (pieces by
/// vertex number are scattered on a subdivided scan: their faces span most of the mesh). Not for
/// the paper's λ rule (opt.h2k = PaperLambda: λ is a whole-mesh minimum).
double activeEnergyInPieces(const Topology& topo, const std::vector<Vec3>& p, const std::vector<std::uint8_t>& active,
                            VertexArea area, const CurvatureOptions& opt, int pieceVertices);

}  // namespace elastica
