// SPDX-License-Identifier: GPL-3.0-or-later
// The discrete bending energy that the vector scheme descends, with its exact gradient:
//   W(X) = Σ_i ( |y_i|² / A_i − 2 K_i A_i ),   y_i = Σ_j C_ij (X_j − X_i) = A_i Δ_B X_i = 2 A_i H⃗_i,
// over the counted vertices i (active, interior, with an area), C the cotangent weights, A_i the
// vertex areas (mixed or barycentric, as the geometry) and K_i A_i = 2π − Σ angles. Where the
// Laplacian of the positions is normal, |y_i|²/A_i = 4 H_i² A_i and W is the paper's
// E = Σ (4H² − 2K) A; its tangential part adds to W, so descending W also moves vertices towards
// a mesh whose Laplacian is normal (Barrett–Garcke–Nürnberg's "conformal polyhedral" meshes: even
// triangles without remeshing). Being the gradient of the energy the step is judged by, a small
// enough step always lowers it: no step is rejected for want of a descent direction.
#pragma once

#include <elastica/geometry.h>
#include <elastica/topology.h>
#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// Scratch and results of one evaluation; reused between steps (no allocation once sized).
struct BendingEnergy {
  std::vector<Vec3> y;          ///< per vertex: A_i Δ_B X_i (zero where not counted)
  std::vector<Vec3> gradient;   ///< per vertex: ∂W/∂X_i (gradient() only)
  std::vector<double> faceGrad; ///< per face: 9 partials (gradient() scratch)
  std::vector<double> term;     ///< per vertex: its term of W (with a third of its faces' barrier)
  double value = 0;
};

/// Whether vertex i carries a term of W: `active[i]`, not on the boundary, with an area.
inline bool countedInBending(const Topology& topo, const Geometry& geo, const std::vector<std::uint8_t>& active, int i) {
  return active[i] && !topo.isBoundaryVertex(i) && geo.vertexArea[i] > 0;
}

/// The second derivative of a corner's needle barrier in its angle θ (0 at angles of θ₀ = 10° and
/// more), for a corner of cotangent `cot` (taken as 1° below 1°): the barrier's stiffness, which the
/// vector scheme's matrix adds (vector_integrator.cpp) so that a step does not overshoot it.
double needleBarrierStiffness(double cot);

/// W at the geometry's positions `p` (fills `out.y` and `out.value`).
double bendingEnergy(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                     const std::vector<std::uint8_t>& active, BendingEnergy& out);

/// W and ∂W/∂X for every vertex (fills `out.gradient`; entries of vertices no counted term
/// depends on are zero). Differentiates exactly what bendingEnergy() sums, but for cotangents
/// that the geometry clamps (angles under ~0.06°).
void bendingGradient(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                     const std::vector<std::uint8_t>& active, BendingEnergy& out);

}  // namespace elastica
