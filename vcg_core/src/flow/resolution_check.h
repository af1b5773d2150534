// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a mesh resolves the surface it stands for (issue 40): Loop's limit surface is smooth, so
// a mesh that resolves its shape keeps its energy E under one Loop subdivision; one that lets a
// tunnel or a neck pinch below what its edges resolve counts the pinch as nearly free, and the
// subdivided mesh shows what it costs (the elephant's pin-hole tunnels: E 143.8, once subdivided
// 187.0). The flow checks its own result with it before it says `converged`, and refines where
// the gap is (fairing.cpp). bench/loop_energy.py measures the same for any file.
#pragma once

#include <elastica/flow.h>
#include <elastica/types.h>

#include <cstdint>
#include <vector>

namespace elastica {

/// A result is resolved when its Loop-subdivided energy is at most this fraction above its own.
inline constexpr double kResolvedGap = 0.02;

/// A mesh's energy beside its Loop subdivision's, and where the difference lies.
struct Resolution {
  double energy = 0;      ///< E of the mesh (the flow's vertex areas and curvature options)
  double loopEnergy = 0;  ///< E of the mesh Loop-subdivided once
  /// Per vertex: 1 where the subdivision's energy rose most: the vertices (and their one-rings)
  /// whose rise per unit area is twice its mean over the mesh; every vertex if none is (the gap is
  /// spread evenly).
  std::vector<std::uint8_t> unresolved;
  /// (loopEnergy − energy) / max(|energy|, 1).
  double gap() const;
  bool resolved() const { return gap() <= kResolvedGap; }
};

/// Measures `mesh` (closed: Loop's masks need no border) with `opt`'s operators. False, and
/// `out` untouched, if the mesh has a border or a non-manifold edge.
bool measureResolution(const TriMesh& mesh, const FlowOptions& opt, Resolution& out);

}  // namespace elastica
