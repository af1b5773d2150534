// SPDX-License-Identifier: GPL-3.0-or-later
// What fair(mesh, region) promises of its output, checked on the output itself: a flow run can
// end in a state that no single step's guard caught (a remeshing that stacks vertices at one
// point, a region that crossed itself before the embedding guard was asked, a time limit in a
// state above the start). A region's run must never hand such a mesh back, so its result is
// checked against its input as a whole, and refused if it fails (fairing.cpp keeps the input then).
#pragma once

#include <elastica/flow.h>
#include <elastica/types.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace elastica {

/// The energy Σ (4H² − 2K) A over the vertices of the flagged faces (`faces` empty: all), with
/// `opt`'s vertex areas and curvature: what the whole mesh gives those vertices, computed on them
/// and their neighbouring faces only.
double regionEnergy(const TriMesh& mesh, const std::vector<std::uint8_t>& faces, const FlowOptions& opt);

/// The input of a region's run, measured once, and the checks of an output against it.
class RegionGuard {
 public:
  /// `selection`: one byte per face of `input` (non-zero: in the region); `opt`: the run's vertex
  /// area and curvature options, with which the region's energy is measured.
  /// @throws InvalidInputError if the input's connectivity is bad (Topology's).
  RegionGuard(const TriMesh& input, const std::vector<std::uint8_t>& selection, const FlowOptions& opt);

  /// The energy Σ (4H² − 2K) A over the vertices of the region's faces (the region and its fixed
  /// rings; interior regular vertices, as the flow's energy) of the input.
  double energyBefore() const { return before_.energy; }

  /// Checks `output` (with `selection`, its region's flags) against the input: a manifold mesh
  /// (no edge on three faces, one fan per vertex, consistently oriented, beyond the input's own); no two vertices of the
  /// region's faces and their neighbours at one point, beyond the input's own; no more faces
  /// crossing another there than in the input; every face off the region as in the input, bit for
  /// bit (with subdivision, but for the faces along the region, which it splits); the region's
  /// energy, at the output's resolution, not above the input's. Returns "" if it
  /// passes, else what failed first, in words. `energyAfter` receives the output region's energy
  /// (NaN if the mesh is not manifold enough to measure).
  std::string check(const TriMesh& output, const std::vector<std::uint8_t>& selection, double& energyAfter) const;

 private:
  struct Measure {
    double energy = 0;
    int coincident = 0;  // vertices of the region's faces and their neighbours at a point already taken
    int crossing = 0;    // faces there crossing another face
  };
  Measure measure(const TriMesh& mesh, const std::vector<std::uint8_t>& selection) const;

  using FaceKey = std::array<std::uint64_t, 9>;  // a face's corners' bits, from its least corner
  // With `splitsNeighbours` (a subdivided region splits the faces sharing an edge with it, to stay
  // conforming), faces with two corners on the region are left out.
  static std::vector<FaceKey> outsideFaces(const TriMesh& mesh, const std::vector<std::uint8_t>& selection,
                                           bool splitsNeighbours);

  FlowOptions opt_;
  bool splitsNeighbours_ = false;
  Measure before_;
  std::vector<FaceKey> outside_;  // sorted
  int nonManifoldVertices_ = 0, inconsistentEdges_ = 0;  // the input's own
};

}  // namespace elastica
