// SPDX-License-Identifier: GPL-3.0-or-later
// The cotangent Laplace–Beltrami operator (the paper's eq. 2.6 with Meyer et al.'s normalisation):
//   (Δ_B f)_i = (1/A_i) Σ_j C_ij (f_j − f_i),   C_ij = ½(cot α_ij + cot β_ij).
// On a smooth surface Δ_B P = 2H N. The paper prints 3/A with the full cotangent sum, which is
// twice this: taken literally, H doubles and a round sphere is not a fixed point of the flow.
#pragma once

#include <elastica/geometry.h>

#include <vector>

namespace elastica {

/// Δ_B of the positions: out[i] = (1/A_i) Σ_j C_ij (p_j − p_i); zero where A_i = 0.
void cotanLaplacian(const Topology& topo, const Geometry& g, const std::vector<Vec3>& p, std::vector<Vec3>& out);

/// The same with the weights given: C_ij per edge of `topo` and A_i per vertex (operators kept
/// from another state of the mesh, as the fairing amount's filter keeps the input's).
void cotanLaplacian(const Topology& topo, const std::vector<double>& edgeWeight, const std::vector<double>& vertexArea,
                    const std::vector<Vec3>& p, std::vector<Vec3>& out);

/// Δ_B of a per-vertex scalar field f.
void cotanLaplacian(const Topology& topo, const Geometry& g, const std::vector<double>& f,
                    std::vector<double>& out);

}  // namespace elastica
