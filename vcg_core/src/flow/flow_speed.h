// SPDX-License-Identifier: GPL-3.0-or-later
// The normal speed of the fourth-order flows, written once: both schemes call it, so the explicit
// step and the semi-implicit right-hand side cannot drift apart.
#pragma once

namespace elastica {

/// F at one vertex from Δ_B H (`laplacianOfH`), H (as the flow uses it) and g = H² − K (clamped):
/// the elastica flow's −Δ_B H − 2H(H² − K) (`elastica`), or the Laplacian-of-H flow's −Δ_B H.
/// Paper sign convention (H = −1/r on an outward sphere): moving by F along N decreases E.
inline double normalSpeed(bool elastica, double laplacianOfH, double H, double g) {
  return -laplacianOfH - (elastica ? 2 * H * g : 0.0);
}

}  // namespace elastica
