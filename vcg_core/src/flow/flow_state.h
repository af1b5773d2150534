// SPDX-License-Identifier: GPL-3.0-or-later
// The state of a flow at one resolution: the moving region (the mesh with its topology and vertex
// roles, built once per connectivity: flow/moving_region.h), and the per-step caches (geometry, curvature, energy, active areas) that a step
// reads without allocating. The integrators (explicit_integrator.h, semi_implicit_integrator.h)
// move its positions; the schedule (fairing.cpp) calls maintain() between steps.
#pragma once

#include <elastica/curvature.h>
#include <elastica/flow.h>
#include <elastica/geometry.h>
#include <elastica/topology.h>
#include "flow/boundary_slide.h"
#include "flow/constraints.h"
#include "flow/internal_flow_options.h"
#include "flow/moving_region.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace elastica {

class FlowState {
 public:
  /// The state of `region` (whose mode must be opt.boundary), keeping its topology and roles if
  /// it has them. `slider` (Slide mode) must outlive the state.
  /// @throws InvalidInputError on bad connectivity.
  FlowState(MovingRegion region, const FlowOptions& opt, const InternalFlowOptions& internal, BoundarySlider* slider);
  /// `faceSelected`: one byte per face, or empty for all faces.
  FlowState(TriMesh mesh, const std::vector<std::uint8_t>& faceSelected, const FlowOptions& opt,
            const InternalFlowOptions& internal, BoundarySlider* slider)
      : FlowState(MovingRegion(std::move(mesh), faceSelected, opt.boundary), opt, internal, slider) {}

  const FlowOptions& options() const { return opt_; }
  const InternalFlowOptions& internalOptions() const { return internal_; }
  const TriMesh& mesh() const { return region_.mesh(); }
  const Topology& topology() const { return region_.topology(); }
  const VertexRoles& roles() const { return region_.roles(); }
  /// The region as the flow has left it (its topology and roles with it); the state is not to be
  /// used after.
  MovingRegion releaseRegion() { return std::move(region_); }
  /// The face selection and the boundary slider the state was made with (to make it again).
  const std::vector<std::uint8_t>& selection() const { return region_.selection(); }
  BoundarySlider* slider() const { return slider_; }
  /// A number no other connectivity of any state had: it changes whenever this state's topology
  /// and roles are rebuilt, so an integrator knows when its per-topology data is stale.
  long long connectivityVersion() const { return connectivityVersion_; }

  /// Replaces the positions (e.g. to roll back to a checkpoint).
  void setPositions(const std::vector<Vec3>& p);
  /// The positions, for an integrator to move; call invalidate() after moving them.
  std::vector<Vec3>& positions() { return region_.positions(); }
  void invalidate() { evaluated_ = geometryEvaluated_ = energyEvaluated_ = false; }
  /// Frees the geometry, the curvature and the copies that let an evaluation keep unchanged
  /// faces' values, until the next evaluation makes them again (whole: the same values): for a
  /// caller whose own data is the run's peak meanwhile (the fairing amount's factor). From then
  /// on no evaluation keeps those copies: each computes every face, as the first did; and above
  /// `energyPieceVertices` vertices energy() and lambda() hold no whole-mesh geometry either: the
  /// energy is measured a piece at a time (flow/energy_in_pieces.h, the same bits), λ is 1 (the
  /// clamp's; the paper's λ rule keeps the whole evaluation).
  void releaseCaches(int energyPieceVertices = 1 << 15);
  double lambda() { return energyInPieces() ? 1.0 : (evaluate(), curv_.lambda); }

  /// Geometry, curvature and energy of the current positions; cached until they change.
  void evaluate();
  /// Geometry and the active areas only (what a tangential pass needs).
  void evaluateGeometry();
  /// Total curvature energy of the active region (free vertices and ring 1).
  double energy();
  /// Area of the faces with a moving vertex: the length² scale of the energy-rate test.
  double activeArea() { evaluateGeometry(); return activeArea_; }
  /// Smallest non-degenerate face area in the moving region (the paper's A_k).
  double activeMinFaceArea() { evaluateGeometry(); return activeMinArea_; }
  /// activeMinFaceArea() of the evaluated geometry, refused if a sliver would make the explicit
  /// step τ ∝ A_min² vanish. @throws InvalidInputError.
  double checkedMinArea() const;
  const Geometry& geometry() { evaluate(); return geo_; }
  /// The geometry without the curvature (a tangential pass, a fold check need no more).
  const Geometry& geometryOnly() { evaluateGeometry(); return geo_; }
  const Curvature& curvature() { evaluate(); return curv_; }
  /// Δ_B P of the last evaluation (curvature's scratch; Δ_B P = 2HN).
  const std::vector<Vec3>& laplacianOfPositions() const { return lp_; }

  /// Between steps: keeps the total area at `area` when nothing pins the scale (a closed surface
  /// whose every vertex moves under the elastica flow: E does not see the scale, and long runs
  /// drift in size), and flips non-Delaunay edges if FlowOptions::flipEdges.
  void maintain(double area);
  /// Moves the sliding boundary vertices a step along the boundary (BoundaryMode::Slide).
  void slideBoundary();

 private:
  void buildConnectivity();
  void normalizeArea(double area);
  bool mayFlip();

  MovingRegion region_;  // the mesh, the selection and the boundary mode, with topology and roles
  FlowOptions opt_;
  InternalFlowOptions internal_;
  BoundarySlider* slider_;
  long long connectivityVersion_ = 0;
  int checksSinceFlipSearch_ = 0;  // InternalFlowOptions::flipInterval
  bool evaluated_ = false;          // geometry and curvature of the current positions
  bool geometryEvaluated_ = false;  // geometry (and active areas) only
  bool energyEvaluated_ = false;    // the energy is computed when asked for, not at every explicit step
  bool scaleFree_ = false;
  bool keepForReuse_ = true;  // evaluatedPositions_ and evaluatedFaces_ (releaseCaches ends it)
  int energyPieceVertices_ = 0;  // releaseCaches': measure energy() in pieces above this many vertices
  bool energyInPieces() const {
    return !keepForReuse_ && opt_.curvature.h2k != H2KTreatment::PaperLambda &&
           topology().vertexCount() > energyPieceVertices_;
  }

  Geometry geo_;
  std::vector<Vec3> evaluatedPositions_;  // what geo_ was last computed from (empty: nothing to keep)
  std::vector<Face> evaluatedFaces_;
  long long evaluatedConnectivity_ = -1;
  std::vector<std::uint8_t> moved_, keptFaces_, keptEdges_;
  Curvature curv_;
  double energy_ = 0, activeArea_ = 0, activeMinArea_ = 0;
  std::vector<Vec3> lp_;
};

}  // namespace elastica
