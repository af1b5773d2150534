// SPDX-License-Identifier: GPL-3.0-or-later
// Discrete mean and Gaussian curvature and the H² − K term of the elastica speed.
#pragma once

#include <elastica/geometry.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// How the flow treats vertices where the discrete H² − K is negative (impossible on a smooth
/// surface; H and K carry different discretisation errors).
enum class H2KTreatment {
  /// Continuous clamp g = max(H² − K, 0) (default). Converges where the λ rule does not.
  Clamp,
  /// The paper's rule, guarded: on D = {active, interior, H ≠ 0, H² < K, K above a scale-relative floor},
  /// λ = min_D |H|/√K, bounded below by `lambdaFloor`, and H ← H/λ on D; then clamp. Unguarded,
  /// a near-flat patch gave λ ≈ 3e-8 and the flow exploded.
  PaperLambda,
};

struct CurvatureOptions {
  H2KTreatment h2k = H2KTreatment::Clamp;
  /// λ is never below this (the paper's rule only rescales by a modest factor once the mesh is fair).
  double lambdaFloor = 0.5;
  /// Vertices join D only if K·ℓ² exceeds this (ℓ the mean edge length): near-flat vertices
  /// have K at the noise level and would make λ arbitrary.
  double relativeKFloor = 1e-6;
};

/// Per-vertex curvatures, in the paper's sign convention (see sign_convention.h).
struct Curvature {
  std::vector<double> H;      ///< raw mean curvature ½ N·Δ_B P (−1/r on an outward sphere)
  std::vector<double> K;      ///< angle-deficit Gaussian curvature (2π − Σφ)/A (π at boundary)
  std::vector<double> Hflow;  ///< H as the flow uses it (H/λ on D with PaperLambda, else H)
  std::vector<double> g;      ///< the flow's H² − K term, ≥ 0 (clamped)
  double lambda = 1;          ///< the paper's λ (1 with Clamp)
  std::size_t lambdaVertices = 0;  ///< |D|: vertices rescaled by λ
  std::size_t clampedVertices = 0; ///< vertices where H² − K < 0 was clamped to 0
};

/// Computes curvatures into `out` (reusing storage). `active`, if given (one byte per vertex),
/// restricts the λ rule to the moving region; H and K are computed everywhere. Vertices with no
/// usable area (Geometry::isRegular false) get H = K = 0.
/// `laplacianOfP` is scratch storage for Δ_B P (kept for the caller: Δ_B P = 2HN).
void computeCurvature(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                      const CurvatureOptions& opt, Curvature& out, std::vector<Vec3>& laplacianOfP,
                      const std::vector<std::uint8_t>* active = nullptr);

/// Convenience overload.
Curvature computeCurvature(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                           const CurvatureOptions& opt = {});

}  // namespace elastica
