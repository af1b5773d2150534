// The state of a flow at one resolution: the mesh, its topology and vertex roles (built once per
// connectivity), and the per-step caches (geometry, curvature, speeds) that a step reuses without
// allocating. An integrator step reads the cached operators and moves the free vertices.
#pragma once

#include <elastica/curvature.h>
#include <elastica/flow.h>
#include <elastica/geometry.h>
#include <elastica/topology.h>
#include "flow/boundary_slide.h"
#include "flow/constraints.h"
#include "flow/tangential.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace elastica {

class FlowState {
 public:
  /// `faceSelected`: one byte per face, or empty for all faces. `slider` (Slide mode) must outlive
  /// the state. @throws InvalidInputError on bad connectivity.
  FlowState(TriMesh mesh, const std::vector<std::uint8_t>& faceSelected, const FlowOptions& opt,
            BoundarySlider* slider);

  const TriMesh& mesh() const { return mesh_; }
  const Topology& topology() const { return topo_; }
  const VertexRoles& roles() const { return roles_; }
  /// Replaces the positions (e.g. to roll back to a checkpoint).
  void setPositions(const std::vector<Vec3>& p);

  /// Geometry, curvature and energy of the current positions; cached until they change.
  void evaluate();
  /// Total curvature energy of the active region (free vertices and ring 1).
  double energy();
  double lambda() { evaluate(); return curv_.lambda; }
  /// Area of the faces with a moving vertex: the length² scale of the energy-rate test.
  double activeArea() { evaluateGeometry(); return activeArea_; }
  /// Smallest non-degenerate face area in the moving region (the paper's A_k).
  double activeMinFaceArea() { evaluateGeometry(); return activeMinArea_; }
  const Geometry& geometry() { evaluate(); return geo_; }
  /// Bytes held by the arrays an explicit step reads or writes (positions, topology, roles,
  /// geometry, curvature and scratch): the memory traffic floor of one step if each were touched
  /// once. For the benchmarks' bandwidth reference.
  std::size_t stepWorkingSetBytes() const;
  const Curvature& curvature() { evaluate(); return curv_; }

  /// One explicit step: paper eq. 2.3 for the elastica and Laplacian-of-H flows (with the
  /// tangential drift if enabled), P ← P − τU0²(P) for the bilaplacian. Returns the flow time
  /// advanced. @throws NumericalError if a position became non-finite (positions then undefined:
  /// roll back); InvalidInputError if a sliver makes the explicit step vanish.
  double explicitStep();

  /// Between steps: keeps the total area at `area` when nothing pins the scale (a closed surface
  /// whose every vertex moves under the elastica flow: E does not see the scale, and long runs
  /// drift in size), and flips non-Delaunay edges if FlowOptions::flipEdges.
  void maintain(double area);

  /// One semi-implicit attempt with step `tau` (Scheme::SemiImplicit). On success the positions
  /// move, tangential drift passes follow, and it returns true; if the step fails (the energy
  /// rises, a face flips, a vertex jumps, a value is non-finite) the positions are unchanged and it
  /// returns false.
  bool trySemiImplicitStep(double tau);
  /// The largest normal displacement |δ_i| of the last accepted semi-implicit step.
  double lastNormalStep() const { return lastNormalStep_; }

 private:
  double normalStep();
  double bilaplacianStep();
  void slideBoundary();
  double checkedMinArea() const;
  void speed(std::vector<double>& F);
  void buildConnectivity();
  void normalizeArea(double area);
  bool mayFlip();
  /// Evaluates the moved positions: no active face turned over since faceNormalBefore_, finite
  /// energy, at most `energyLimit` (elastica).
  bool acceptable(double energyLimit);
  /// One tangential drift pass; undone (returns false) if the result is not acceptable().
  bool driftPass(double energyLimit);
  void evaluateGeometry();
  void invalidate() { evaluated_ = geometryEvaluated_ = false; }

  TriMesh mesh_;
  FlowOptions opt_;
  std::vector<std::uint8_t> selection_;
  Topology topo_;
  VertexRoles roles_;
  BoundarySlider* slider_;
  bool evaluated_ = false;          // geometry and curvature of the current positions
  bool geometryEvaluated_ = false;  // geometry (and active areas) only
  bool energyEvaluated_ = false;  // the energy is computed when asked for, not at every explicit step
  bool scaleFree_ = false;

  Geometry geo_;
  Curvature curv_;
  double energy_ = 0, activeArea_ = 0, activeMinArea_ = 0, lastNormalStep_ = 0;
  std::vector<Vec3> lp_, u_, drift_;
  DriftScratch driftScratch_;
  std::vector<double> lh_, speed_, delta_;
  std::vector<Vec3> saved_, driftSaved_, faceNormalBefore_;
  std::vector<int> freeIndex_;  // vertex → row of the semi-implicit system, or -1
  struct SparseSolver;          // Eigen's factorisation, pattern analysed once per topology
  std::shared_ptr<SparseSolver> solver_;
};

}  // namespace elastica
