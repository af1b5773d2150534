// SPDX-License-Identifier: GPL-3.0-or-later
// What both integrators (vector and semi-implicit) allow a refused step before τ is halved: a step
// refused for a few vertices (faces turned over at their corners, an energy rise that a few
// vertices' terms account for, faces about to cross) is tried again with those vertices and their
// rings held where they were. The dino lost 9 attempts in a row to one face turning over, and the
// ×0.5 that each refusal cost τ took 30 more steps to win back.
#pragma once

namespace elastica {

/// Culprits held per round, and rounds, before the step is refused.
constexpr int kMaxCulprits = 16, kMaxHoldRounds = 3;
/// Faces about to cross hold their free corners (and rings) too; a contact zone spans more
/// vertices than a turned face does.
constexpr int kMaxContactCulprits = 4 * kMaxCulprits;

}  // namespace elastica
