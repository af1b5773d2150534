#include <elastica/energy.h>
#include <elastica/errors.h>
#include "flow/flow_state.h"
#include "mesh/edge_flips.h"
#include "support/parallel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>

namespace elastica {
namespace {

// A face smaller than this (relative to ℓ²) in the moving region would make the explicit step
// τ ∝ A_min² vanish (1e-12 ℓ⁴/150): refuse instead of freezing.
constexpr double kMinRelativeFaceArea = 1e-6;
// Fraction of the way to the midpoint of its boundary neighbours that a sliding vertex moves per step.
constexpr double kSlideRate = 0.1;

}  // namespace

FlowState::FlowState(TriMesh mesh, const std::vector<std::uint8_t>& faceSelected, const FlowOptions& opt,
                     const InternalFlowOptions& internal, BoundarySlider* slider)
    : mesh_(std::move(mesh)),
      opt_(opt),
      internal_(internal),
      selection_(faceSelected),
      topo_(mesh_.vertexCount(), mesh_.faces),
      slider_(slider) {
  buildConnectivity();
}

void FlowState::buildConnectivity() {
  roles_ = assignRoles(topo_, &selection_, opt_.boundary);
  if (slider_ && roles_.slidingCount > 0) slider_->attach(topo_, mesh_.positions, roles_.sliding);
  int used = 0;
  for (int v = 0; v < topo_.vertexCount(); ++v) used += !topo_.isIsolatedVertex(v);
  scaleFree_ = opt_.flow == FlowType::Elastica && topo_.boundaryEdgeCount() == 0 && roles_.freeCount == used;
  static std::atomic<long long> rebuilds{0};
  connectivityVersion_ = ++rebuilds;  // an integrator's per-topology data (rows, sparsity pattern) is stale
  invalidate();
}

void FlowState::maintain(double area) {
  if (scaleFree_) normalizeArea(area);
  if (!opt_.flipEdges || ++checksSinceFlipSearch_ < internal_.flipInterval) return;
  checksSinceFlipSearch_ = 0;
  if (mayFlip() && flipToDelaunay(mesh_, roles_.free) > 0) {
    topo_ = Topology(mesh_.vertexCount(), mesh_.faces);
    buildConnectivity();
  }
}

// Whether flipToDelaunay could flip anything: an edge between free vertices is non-Delaunay
// exactly when its cotangent weight ½(cot α + cot β) is negative (α + β > π). Saves rebuilding the
// adjacency for the flip search after almost every step, when nothing is to flip.
bool FlowState::mayFlip() {
  evaluate();
  if (geo_.degenerate.zeroAreaFaces > 0) return true;  // zero cotangents say nothing there
  for (int e = 0; e < topo_.edgeCount(); ++e) {
    const auto& ev = topo_.edgeVertices(e);
    if (geo_.edgeWeight[e] < 0 && roles_.free[ev[0]] && roles_.free[ev[1]] && !topo_.isBoundaryEdge(e)) return true;
  }
  return false;
}

// Rescales about the centroid to total area `area` (E is unchanged). Only for scale-free meshes,
// where every face is active.
void FlowState::normalizeArea(double area) {
  const double now = activeArea();
  if (!(now > 0) || !(area > 0)) return;
  const double s = std::sqrt(area / now);
  Vec3 c = Vec3::Zero();
  int n = 0;
  for (int v = 0; v < topo_.vertexCount(); ++v)
    if (!topo_.isIsolatedVertex(v)) c += mesh_.positions[v], ++n;
  c /= std::max(n, 1);
  for (int v = 0; v < topo_.vertexCount(); ++v)
    if (!topo_.isIsolatedVertex(v)) mesh_.positions[v] = c + s * (mesh_.positions[v] - c);
  invalidate();
}

void FlowState::setPositions(const std::vector<Vec3>& p) {
  mesh_.positions = p;
  invalidate();
}

void FlowState::evaluateGeometry() {
  if (geometryEvaluated_) return;
  computeGeometry(topo_, mesh_.positions, opt_.area, geo_);
  struct Tally {
    double area = 0, minArea = std::numeric_limits<double>::infinity();
  };
  const double floor = 1e-12 * geo_.meanEdgeLength * geo_.meanEdgeLength;
  const Tally t = parallelReduce(topo_.faceCount(), Tally{}, [&](int f, Tally& tally) {
    if (!roles_.activeFace[f]) return;
    tally.area += geo_.faceArea[f];
    if (geo_.faceArea[f] > floor) tally.minArea = std::min(tally.minArea, geo_.faceArea[f]);
  }, [](Tally& a, const Tally& b) {
    a.area += b.area;
    a.minArea = std::min(a.minArea, b.minArea);
  });
  activeArea_ = t.area;
  activeMinArea_ = std::isfinite(t.minArea) ? t.minArea : 0.0;
  geometryEvaluated_ = true;
}

void FlowState::evaluate() {
  if (evaluated_) return;
  evaluateGeometry();
  computeCurvature(topo_, geo_, mesh_.positions, opt_.curvature, curv_, lp_, &roles_.active);
  if (opt_.boundary == BoundaryMode::Slide) {
    // A boundary vertex's H is one-sided; its free neighbours need one for Δ_B H. Use the mean of
    // its interior neighbours (a zero normal derivative of H across the boundary).
    for (int v = 0; v < topo_.vertexCount(); ++v) {
      if (!topo_.isBoundaryVertex(v)) continue;
      double sum = 0;
      int n = 0;
      for (int k = topo_.ringBegin(v); k < topo_.ringEnd(v); ++k) {
        const int j = topo_.ringVertex(k);
        if (!topo_.isBoundaryVertex(j)) sum += curv_.Hflow[j], ++n;
      }
      curv_.Hflow[v] = n ? sum / n : 0.0;
    }
  }
  energyEvaluated_ = false;
  evaluated_ = true;
}

double FlowState::energy() {
  evaluate();
  if (!energyEvaluated_) {
    energy_ = totalCurvatureEnergy(topo_, geo_, curv_, &roles_.active);
    energyEvaluated_ = true;
  }
  return energy_;
}

double FlowState::checkedMinArea() const {
  const double ell2 = geo_.meanEdgeLength * geo_.meanEdgeLength;
  if (!(activeMinArea_ > kMinRelativeFaceArea * ell2)) {
    throw InvalidInputError("a triangle of area " + std::to_string(activeMinArea_) + " (" +
                            std::to_string(activeMinArea_ / ell2) +
                            " of the squared mean edge length) in the moving region makes the explicit step "
                            "tau = A_min^2/150 vanish; remove needle triangles first");
  }
  return activeMinArea_;
}

void FlowState::slideBoundary() {
  if (!slider_ || roles_.slidingCount == 0) return;
  slider_->slide(topo_, mesh_.positions, roles_.sliding, kSlideRate);
  invalidate();
}

}  // namespace elastica
