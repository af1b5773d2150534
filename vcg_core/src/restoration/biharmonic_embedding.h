// SPDX-License-Identifier: GPL-3.0-or-later
// A linear start for a patch: the free vertices solve the bi-Laplace equation Δ²x = 0 with the
// rest of the mesh as boundary condition (CGAL's fairing, one sparse solve). A flat fill of a deep
// hole folds over and stalls a curvature flow; this smooth, G¹-continuing start does not.
#pragma once

#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Moves the vertices flagged in `free` to the solution of (C M⁻¹ C) x = 0 on them — C the
/// cotangent matrix and M the mixed vertex areas of the current positions — with every other
/// vertex fixed. Each free vertex must be at least two rings away from the mesh boundary (so that
/// its Δ² stencil is complete). `iterations` > 1 re-solves with weights from the previous solution.
/// If the cotangent system cannot be factored (a badly shaped start), uniform weights are used.
/// @throws NumericalError if no solution is finite; positions are then unchanged.
void solveBiharmonic(TriMesh& mesh, const std::vector<std::uint8_t>& free, int iterations = 2);

}  // namespace elastica
