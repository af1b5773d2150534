// SPDX-License-Identifier: GPL-3.0-or-later
// The operators of the fairing amount's filter (flow/principal_part_filter.h) for
// AmountOperators::Graph: uniform weights and areas from the connectivity and the mean edge alone.
#pragma once

#include <elastica/topology.h>
#include <elastica/types.h>

#include <vector>

namespace elastica {

/// Sets `edgeWeight` to an equilateral triangle's cotangent weight per face of the edge (1/√3
/// inside, 1/(2√3) on the boundary) and `vertexArea` to the vertex's faces × (√3/4)·ℓ̄²/3, ℓ̄ the
/// mean edge of `positions`: the cotangent operators of a mesh of equilateral triangles of that
/// edge with this connectivity, which vertex noise cannot make poor.
void graphAmountOperators(const Topology& topo, const std::vector<Vec3>& positions, std::vector<double>& edgeWeight,
                          std::vector<double>& vertexArea);

}  // namespace elastica
