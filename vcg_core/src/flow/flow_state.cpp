#include <elastica/energy.h>
#include <elastica/errors.h>
#include <elastica/laplacian.h>
#include "flow/flow_state.h"
#include "flow/tangential.h"
#include "mesh/edge_flips.h"
#include "support/parallel.h"

#include "flow/semi_implicit_system.h"
#include "flow/spd_solver.h"

#include <Eigen/SparseCore>

#include <algorithm>
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

// Semi-implicit acceptance: a vertex may move at most this fraction of its mean edge length...
constexpr double kMaxJump = 0.5;
// ...and the energy may not rise by more than this (relative): stricter stalls at the noise floor.
constexpr double kEnergySlack = 1e-4;

}  // namespace

struct FlowState::SparseSolver {
  SemiImplicitSystem system;
  SpdSolver spd;
  Eigen::VectorXd delta;
  bool analysed = false;
};

FlowState::FlowState(TriMesh mesh, const std::vector<std::uint8_t>& faceSelected, const FlowOptions& opt,
                     BoundarySlider* slider)
    : mesh_(std::move(mesh)),
      opt_(opt),
      selection_(faceSelected),
      topo_(mesh_.vertexCount(), mesh_.faces),
      slider_(slider) {
  buildConnectivity();
}

void FlowState::buildConnectivity() {
  roles_ = assignRoles(topo_, &selection_, opt_.boundary);
  if (slider_ && roles_.slidingCount > 0) slider_->attach(topo_, mesh_.positions, roles_.sliding);
  freeIndex_.assign(topo_.vertexCount(), -1);
  int row = 0, used = 0;
  for (int v = 0; v < topo_.vertexCount(); ++v) {
    if (roles_.free[v]) freeIndex_[v] = row++;
    used += !topo_.isIsolatedVertex(v);
  }
  scaleFree_ = opt_.flow == FlowType::Elastica && topo_.boundaryEdgeCount() == 0 && roles_.freeCount == used;
  solver_.reset();  // the sparsity pattern follows the connectivity
  invalidate();
}

void FlowState::maintain(double area) {
  if (scaleFree_) normalizeArea(area);
  if (opt_.flipEdges && mayFlip() && flipToDelaunay(mesh_, roles_.free) > 0) {
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

std::size_t FlowState::stepWorkingSetBytes() const {
  auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  return topo_.byteSize() + bytes(mesh_.positions) + bytes(roles_.free) + bytes(roles_.active) +
         bytes(roles_.activeFace) + bytes(geo_.faceArea) + bytes(geo_.faceNormal) + bytes(geo_.cornerDot) +
         bytes(geo_.cornerCot) + bytes(geo_.cornerArea) + bytes(geo_.edgeLength) + bytes(geo_.edgeWeight) +
         bytes(geo_.vertexArea) + bytes(geo_.ringArea) +
         bytes(geo_.vertexNormal) + bytes(geo_.angleSum) + bytes(curv_.H) + bytes(curv_.K) + bytes(curv_.Hflow) +
         bytes(curv_.g) + bytes(lp_) + bytes(lh_) + bytes(driftScratch_.weight) + bytes(driftScratch_.u) +
         bytes(drift_);
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

double FlowState::explicitStep() {
  evaluate();
  const double dt = opt_.flow == FlowType::Bilaplacian ? bilaplacianStep() : normalStep();
  invalidate();
  slideBoundary();
  return dt;
}

void FlowState::speed(std::vector<double>& F) {
  cotanLaplacian(topo_, geo_, curv_.Hflow, lh_);
  const bool elastica = opt_.flow == FlowType::Elastica;
  const int nv = topo_.vertexCount();
  F.assign(nv, 0.0);
  parallelFor(nv, [&](int i) {
    if (!roles_.free[i]) return;
    // Paper sign convention (H = −1/r on an outward sphere): F = −Δ_B H − 2H(H² − K) decreases E.
    F[i] = -lh_[i] - (elastica ? 2 * curv_.Hflow[i] * curv_.g[i] : 0.0);
  });
}

double FlowState::normalStep() {
  const double aMin = checkedMinArea();
  const double tau = opt_.stepFactor * aMin * aMin;  // paper: τ = A_min²/150
  const double eps = opt_.driftFactor * aMin;        // paper: ε = 12 A_min
  cotanLaplacian(topo_, geo_, curv_.Hflow, lh_);
  const bool drift = opt_.tangentialDrift;
  if (drift) tangentialDrift(topo_, geo_, mesh_.positions, roles_.free, driftScratch_, drift_);
  const bool elastica = opt_.flow == FlowType::Elastica;
  const int nv = topo_.vertexCount();
  const int nonFinite = parallelReduce(nv, 0, [&](int i, int& bad) {
    if (!roles_.free[i]) return;
    // The speed of speed(), inline: F = −Δ_B H − 2H(H² − K) (paper sign convention).
    const double F = -lh_[i] - (elastica ? 2 * curv_.Hflow[i] * curv_.g[i] : 0.0);
    Vec3& p = mesh_.positions[i];
    p += tau * F * geo_.vertexNormal[i];
    if (drift) p += eps * drift_[i];
    bad += !p.allFinite();
  }, [](int& a, int b) { a += b; });
  if (nonFinite > 0) throw NumericalError("a vertex position became non-finite");
  return tau;
}

double FlowState::bilaplacianStep() {
  uniformBiUmbrella(topo_, mesh_.positions, roles_.free, u_, drift_);
  const int nv = topo_.vertexCount();
  const int nonFinite = parallelReduce(nv, 0, [&](int i, int& bad) {
    if (!roles_.free[i]) return;
    mesh_.positions[i] -= opt_.bilaplacianStep * drift_[i];
    bad += !mesh_.positions[i].allFinite();
  }, [](int& a, int b) { a += b; });
  if (nonFinite > 0) throw NumericalError("a vertex position became non-finite");
  // U0² ≈ (ℓ⁴/16) Δ², so this step is worth about bilaplacianStep·ℓ⁴/16 of flow time.
  const double ell = geo_.meanEdgeLength;
  return opt_.bilaplacianStep * ell * ell * ell * ell / 16;
}

void FlowState::slideBoundary() {
  if (!slider_ || roles_.slidingCount == 0) return;
  slider_->slide(topo_, mesh_.positions, roles_.sliding, kSlideRate);
  invalidate();
}

bool FlowState::trySemiImplicitStep(double tau) {
  auto reject = [&] {
    mesh_.positions = saved_;
    invalidate();
    return false;
  };
  evaluate();
  speed(speed_);
  const int nv = topo_.vertexCount(), n = roles_.freeCount;
  if (!solver_) solver_ = std::make_shared<SparseSolver>();

  // (M_ff + τ/2 · C_fa M_aa⁻¹ C_af) δ_f = τ M_ff F_f: to leading order F(P + δN) ≈ F − ½Δ_B²δ,
  // so the stiff fourth-order part is taken at the new time and everything else is lagged.
  SemiImplicitSystem& system = solver_->system;
  system.assemble(topo_, geo_, roles_.active, freeIndex_, n, speed_, tau);
  if (!solver_->analysed) {
    solver_->spd.analyzePattern(system.matrix());  // the pattern depends on the topology only
    solver_->analysed = true;
  }
  saved_ = mesh_.positions;
  if (!solver_->spd.factorize(system.matrix())) return reject();
  Eigen::VectorXd& delta = solver_->delta;
  solver_->spd.solve(system.rhs(), delta);

  const double energyBefore = energy();
  const double energyLimit = energyBefore * (1 + kEnergySlack) + 1e-12;
  faceNormalBefore_ = geo_.faceNormal;
  double largest = 0;
  for (int v = 0; v < nv; ++v) {
    const int r = freeIndex_[v];
    if (r < 0) continue;
    if (!std::isfinite(delta[r])) return reject();
    double ring = 0;
    for (int k = topo_.ringBegin(v); k < topo_.ringEnd(v); ++k)
      ring += (saved_[topo_.ringVertex(k)] - saved_[v]).norm();
    if (std::abs(delta[r]) > kMaxJump * ring / std::max(1, topo_.valence(v))) return reject();
    mesh_.positions[v] += delta[r] * geo_.vertexNormal[v];
    largest = std::max(largest, std::abs(delta[r]));
  }
  invalidate();
  if (!acceptable(energyLimit)) return reject();
  lastNormalStep_ = largest;

  // The drift is held to the same rules: a pass that folds a face or lifts the energy above what
  // the step allowed is undone (and the passes stop), so the step's checks cannot be undone by it.
  for (int pass = 0; pass < opt_.driftPasses && opt_.tangentialDrift; ++pass)
    if (!driftPass(energyLimit)) break;
  // The last evaluation (of the accepted state) stays valid unless the boundary slides.
  slideBoundary();
  return true;
}

bool FlowState::acceptable(double energyLimit) {
  evaluateGeometry();
  for (int f = 0; f < topo_.faceCount(); ++f)
    if (roles_.activeFace[f] && geo_.faceNormal[f].dot(faceNormalBefore_[f]) < 0) return false;
  const double e = energy();
  if (!std::isfinite(e)) return false;
  // The Laplacian-of-H flow is not a descent of E: it is judged by not creating folds only.
  return opt_.flow != FlowType::Elastica || e <= energyLimit;
}

bool FlowState::driftPass(double energyLimit) {
  evaluateGeometry();  // the drift itself needs no curvature
  const double eps = opt_.driftFactor * activeMinArea_;
  tangentialDrift(topo_, geo_, mesh_.positions, roles_.free, driftScratch_, drift_);
  driftSaved_ = mesh_.positions;
  faceNormalBefore_ = geo_.faceNormal;
  const int nv = topo_.vertexCount();
  parallelFor(nv, [&](int i) {
    if (roles_.free[i]) mesh_.positions[i] += eps * drift_[i];
  });
  invalidate();
  if (acceptable(energyLimit)) return true;
  mesh_.positions = driftSaved_;
  invalidate();
  return false;
}

}  // namespace elastica
