// SPDX-License-Identifier: GPL-3.0-or-later
// The one place where the two sign conventions of the mean curvature meet.
//
// Inside the core (the flows) H is the paper's H = ½ N·Δ_B P with area-weighted outward normals:
// on a round sphere of radius r, Δ_B P = −(2/r) N, so H = −1/r. With this sign the elastica speed
// F = −Δ_B H − 2H(H² − K) along N decreases the energy; the opposite sign makes it grow.
//
// Users (files, reports, MeshLab's quality) expect H = +1/r for a convex shape with outward
// normals. Every value that leaves the core through a file, a report or a MeshLab attribute goes
// through reportedMeanCurvature(); nothing else flips the sign.
#pragma once

namespace elastica {

/// Converts the paper's H (−1/r on an outward-oriented sphere) to the reported H (+1/r).
constexpr double reportedMeanCurvature(double paperH) { return -paperH; }

}  // namespace elastica
