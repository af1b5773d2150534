// SPDX-License-Identifier: GPL-3.0-or-later
// The flow's knobs that no face sets: restoration tunes them for a hole's patch (hole_filling.cpp),
// fair() runs with the defaults. They live here, not in FlowOptions, so that the public header
// lists only what a user chooses. The measurements behind the defaults: docs/options.md.
#pragma once

namespace elastica {

struct InternalFlowOptions {
  /// With FlowOptions::flipEdges: look for flips at every flipInterval-th check only (checks).
  int flipInterval = 1;
  /// Semi-implicit: start at a tenth of the region's shape scale (τ = A²/500) instead of 0.05 ℓ⁴.
  bool startAtShapeScale = false;
  /// The farthest a vertex may move in one step, in its mean edge lengths: the semi-implicit scheme
  /// rejects a longer step (along the normal) unless shortenJumps, the vector scheme shortens it.
  double maxJump = 2;
  /// Semi-implicit: shorten a step longer than maxJump to that length instead of rejecting it.
  bool shortenJumps = false;
};

}  // namespace elastica
