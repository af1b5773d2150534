// SPDX-License-Identifier: GPL-3.0-or-later
// The part of a mesh a flow moves, as one value: the mesh, its face selection and the boundary
// mode, with the topology and the vertex roles that follow from them. Both are built when first
// asked for and kept until the connectivity or the selection changes: the schedule, the quality
// stages (flow/mesh_quality_stage.h) and FlowState ask for them many times per stage, and each
// used to build its own (one needsRemeshing() built three topologies and assigned roles twice).
#pragma once

#include <elastica/flow.h>
#include <elastica/topology.h>
#include <elastica/types.h>
#include "flow/constraints.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace elastica {

class MovingRegion {
 public:
  /// `selection`: one byte per face (non-zero: selected), or empty for every face.
  MovingRegion(TriMesh mesh, std::vector<std::uint8_t> selection, BoundaryMode mode)
      : mesh_(std::move(mesh)), selection_(std::move(selection)), mode_(mode) {}

  const TriMesh& mesh() const { return mesh_; }
  const std::vector<std::uint8_t>& selection() const { return selection_; }
  BoundaryMode mode() const { return mode_; }

  /// The mesh's topology, built on first use and kept until the connectivity changes.
  /// @throws InvalidInputError on bad connectivity (Topology's).
  const Topology& topology() const;
  /// assignRoles() of the topology, the selection and the mode, kept as long as the topology.
  const VertexRoles& roles() const;

  /// The positions, to move: the topology and the roles stay, as they do not depend on them.
  std::vector<Vec3>& positions() { return mesh_.positions; }
  /// `move(mesh)` moves vertices and changes nothing else: the topology and the roles stay.
  template <class Move>
  void movePositions(Move&& move) {
    move(mesh_);
  }
  /// Changes the connectivity (subdivision, remeshing, edge flips): `edit(mesh, selection)` may
  /// change both and returns whether it changed anything. The topology and the roles it may read
  /// while it runs are those before; if it changed something (or threw), they are built again when
  /// next asked for. Returns what `edit` returned.
  template <class Edit>
  bool edit(Edit&& edit) {
    bool changed = true;
    try {
      changed = edit(mesh_, selection_);
    } catch (...) {
      invalidate();
      throw;
    }
    if (changed) invalidate();
    return changed;
  }
  /// The time by which work on the region must end (the run's wall-time limit; none by default):
  /// its remeshings (flow/mesh_quality_stage.h) start no round after it and are undone if they end
  /// after it, so that a run keeps its limit also where it remeshes.
  using Deadline = std::chrono::steady_clock::time_point;
  void setDeadline(Deadline deadline) { deadline_ = deadline; }
  Deadline deadline() const { return deadline_; }
  bool pastDeadline() const { return std::chrono::steady_clock::now() >= deadline_; }
  /// A copy that takes this region's topology and roles instead of copying them (this one builds
  /// them again if asked): for a flow stage, which works on its own copy while this one keeps the
  /// mesh as the stage found it, without holding the adjacency twice.
  MovingRegion copyTakingCaches();
  /// The mesh, taken out (the region is left empty).
  TriMesh release();

 private:
  void invalidate() {
    topo_.reset();
    roles_.reset();
  }

  TriMesh mesh_;
  std::vector<std::uint8_t> selection_;
  BoundaryMode mode_;
  Deadline deadline_ = Deadline::max();
  mutable std::optional<Topology> topo_;     // not thread-safe: a region belongs to one run
  mutable std::optional<VertexRoles> roles_;
};

}  // namespace elastica
