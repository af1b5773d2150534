// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/energy.h>
#include <elastica/errors.h>
#include "flow/energy_in_pieces.h"
#include "flow/flow_state.h"
#include "mesh/edge_flips.h"
#include "support/parallel.h"

#ifdef __GLIBC__
#include <malloc.h>
#endif

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

FlowState::FlowState(MovingRegion region, const FlowOptions& opt, const InternalFlowOptions& internal, BoundarySlider* slider)
    : region_(std::move(region)), opt_(opt), internal_(internal), slider_(slider) {
  buildConnectivity();
}

void FlowState::buildConnectivity() {
  const Topology& topo = region_.topology();  // built here if the region had none: throws here
  const VertexRoles& roles = region_.roles();
  if (slider_ && roles.slidingCount > 0) slider_->attach(topo, region_.mesh().positions, roles.sliding);
  int used = 0;
  for (int v = 0; v < topo.vertexCount(); ++v) used += !topo.isIsolatedVertex(v);
  scaleFree_ = opt_.flow == FlowType::Elastica && topo.boundaryEdgeCount() == 0 && roles.freeCount == used;
  static std::atomic<long long> rebuilds{0};
  connectivityVersion_ = ++rebuilds;  // an integrator's per-topology data (rows, sparsity pattern) is stale
  invalidate();
}

void FlowState::maintain(double area) {
  if (scaleFree_) normalizeArea(area);
  if (!opt_.flipEdges || ++checksSinceFlipSearch_ < internal_.flipInterval) return;
  checksSinceFlipSearch_ = 0;
  // The flips read the roles before the edit; the region drops its topology and roles if any edge
  // flipped, and buildConnectivity() builds them again.
  if (mayFlip() && region_.edit([&](TriMesh& mesh, std::vector<std::uint8_t>&) { return flipToDelaunay(mesh, &topology(), roles().free) > 0; }))
    buildConnectivity();
}

// Whether flipToDelaunay could flip anything: an edge between free vertices is non-Delaunay
// exactly when its cotangent weight ½(cot α + cot β) is negative (α + β > π). Saves rebuilding the
// adjacency for the flip search after almost every step, when nothing is to flip.
bool FlowState::mayFlip() {
  evaluate();
  if (geo_.degenerate.zeroAreaFaces > 0) return true;  // zero cotangents say nothing there
  const Topology& topo = topology();
  const std::vector<std::uint8_t>& free = roles().free;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& ev = topo.edgeVertices(e);
    if (geo_.edgeWeight[e] < 0 && free[ev[0]] && free[ev[1]] && !topo.isBoundaryEdge(e)) return true;
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
  const Topology& topo = topology();
  std::vector<Vec3>& p = region_.positions();
  for (int v = 0; v < topo.vertexCount(); ++v)
    if (!topo.isIsolatedVertex(v)) c += p[v], ++n;
  c /= std::max(n, 1);
  for (int v = 0; v < topo.vertexCount(); ++v)
    if (!topo.isIsolatedVertex(v)) p[v] = c + s * (p[v] - c);
  invalidate();
}

void FlowState::setPositions(const std::vector<Vec3>& p) {
  region_.positions() = p;
  invalidate();
}

void FlowState::releaseCaches(int energyPieceVertices) {
  invalidate();
  keepForReuse_ = false;
  energyPieceVertices_ = energyPieceVertices;
  geo_ = Geometry();
  curv_ = Curvature();
  std::vector<Vec3>().swap(lp_);
  std::vector<Vec3>().swap(evaluatedPositions_);
  std::vector<Face>().swap(evaluatedFaces_);
  std::vector<std::uint8_t>().swap(moved_);
  std::vector<std::uint8_t>().swap(keptFaces_);
  std::vector<std::uint8_t>().swap(keptEdges_);
#ifdef __GLIBC__
  // Give the freed pages back: glibc keeps arrays below its (adaptive, up to 32 MB) mmap threshold
  // on the heap, and a caller that releases to make room for its own peak wants that room in RSS
  // too (the 711k elephant's default: peak RSS 1,042 -> 1,017 MB; docs/decisions.md).
  malloc_trim(0);
#endif
}

void FlowState::evaluateGeometry() {
  if (geometryEvaluated_) return;
  // The per-vertex quantities (areas, normals, angle sums) at the active vertices only: every
  // integrator and the energy read them there (a free vertex and its ring), and a region's piece is
  // mostly fixed rings and obstacles, whose angle sums cost a region's run more than they are worth
  // (docs/decisions.md, "Regions").
  // The faces whose corners, and their positions, are those of the last evaluation keep their
  // values, and so do the edges whose ends did not move on the same connectivity
  // (computeGeometry's GeometryKept): a region's obstacles and fixed rings never move.
  const std::vector<Vec3>& p = region_.positions();
  const Topology& topo = topology();
  const std::vector<Face>& faces = topo.faces();
  GeometryKept kept;
  if (evaluatedPositions_.size() == p.size() && evaluatedFaces_.size() == faces.size() &&
      geo_.faceArea.size() == faces.size()) {
    moved_.resize(p.size());
    for (std::size_t v = 0; v < p.size(); ++v) moved_[v] = p[v] != evaluatedPositions_[v];
    keptFaces_.resize(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Face& t = faces[f];
      keptFaces_[f] = t == evaluatedFaces_[f] && !moved_[t[0]] && !moved_[t[1]] && !moved_[t[2]];
    }
    kept.faces = &keptFaces_;
    if (evaluatedConnectivity_ == connectivityVersion_ && geo_.edgeLength.size() == static_cast<std::size_t>(topo.edgeCount())) {
      keptEdges_.resize(topo.edgeCount());
      for (int e = 0; e < topo.edgeCount(); ++e) keptEdges_[e] = !moved_[topo.edgeVertices(e)[0]] && !moved_[topo.edgeVertices(e)[1]];
      kept.edges = &keptEdges_;
    }
  }
  evaluatedPositions_.clear();  // until this evaluation has succeeded
  computeGeometry(topo, p, opt_.area, geo_, &roles().active, kept);
  if (keepForReuse_) {
    evaluatedPositions_ = p;
    evaluatedFaces_ = faces;
  }
  evaluatedConnectivity_ = connectivityVersion_;
  struct Tally {
    double area = 0, minArea = std::numeric_limits<double>::infinity();
  };
  const double floor = 1e-12 * geo_.meanEdgeLength * geo_.meanEdgeLength;
  const std::vector<std::uint8_t>& activeFace = roles().activeFace;
  const Tally t = parallelReduce(topology().faceCount(), Tally{}, [&](int f, Tally& tally) {
    if (!activeFace[f]) return;
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
  computeCurvature(topology(), geo_, region_.positions(), opt_.curvature, curv_, lp_, &roles().active);
  if (opt_.boundary == BoundaryMode::Slide) {
    // A boundary vertex's H is one-sided; its free neighbours need one for Δ_B H. Use the mean of
    // its interior neighbours (a zero normal derivative of H across the boundary).
    const Topology& topo = topology();
    for (int v = 0; v < topo.vertexCount(); ++v) {
      if (!topo.isBoundaryVertex(v)) continue;
      double sum = 0;
      int n = 0;
      for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) {
        const int j = topo.ringVertex(k);
        if (!topo.isBoundaryVertex(j)) sum += curv_.Hflow[j], ++n;
      }
      curv_.Hflow[v] = n ? sum / n : 0.0;
    }
  }
  energyEvaluated_ = false;
  evaluated_ = true;
}

double FlowState::energy() {
  if (energyInPieces()) {
    if (!energyEvaluated_)
      energy_ = activeEnergyInPieces(topology(), region_.positions(), roles().active, opt_.area, opt_.curvature,
                                     energyPieceVertices_);
    energyEvaluated_ = true;
    return energy_;
  }
  evaluate();
  if (!energyEvaluated_) {
    energy_ = totalCurvatureEnergy(topology(), geo_, curv_, &roles().active);
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
  if (!slider_ || roles().slidingCount == 0) return;
  slider_->slide(topology(), region_.positions(), roles().sliding, kSlideRate);
  invalidate();
}

}  // namespace elastica
