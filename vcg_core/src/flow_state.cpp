#include <elastica/edge_flips.h>
#include <elastica/energy.h>
#include <elastica/errors.h>
#include <elastica/flow_state.h>
#include <elastica/laplacian.h>
#include <elastica/parallel.h>
#include <elastica/tangential.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

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
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  std::vector<Eigen::Triplet<double>> triplets;
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
  evaluated_ = false;
}

void FlowState::maintain(double area) {
  if (scaleFree_) normalizeArea(area);
  if (opt_.flipEdges && flipToDelaunay(mesh_, roles_.free) > 0) {
    topo_ = Topology(mesh_.vertexCount(), mesh_.faces);
    buildConnectivity();
  }
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
  evaluated_ = false;
}

void FlowState::setPositions(const std::vector<Vec3>& p) {
  mesh_.positions = p;
  evaluated_ = false;
}

void FlowState::evaluate() {
  if (evaluated_) return;
  computeGeometry(topo_, mesh_.positions, opt_.area, geo_);
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
  energy_ = totalCurvatureEnergy(topo_, geo_, curv_, &roles_.active);
  activeArea_ = 0;
  activeMinArea_ = std::numeric_limits<double>::infinity();
  const double floor = 1e-12 * geo_.meanEdgeLength * geo_.meanEdgeLength;
  for (int f = 0; f < topo_.faceCount(); ++f) {
    if (!roles_.activeFace[f]) continue;
    activeArea_ += geo_.faceArea[f];
    if (geo_.faceArea[f] > floor) activeMinArea_ = std::min(activeMinArea_, geo_.faceArea[f]);
  }
  if (!std::isfinite(activeMinArea_)) activeMinArea_ = 0;
  evaluated_ = true;
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
  slideBoundary();
  evaluated_ = false;
  return dt;
}

void FlowState::speed(std::vector<double>& F) {
  cotanLaplacian(topo_, geo_, curv_.Hflow, lh_);
  const bool elastica = opt_.flow == FlowType::Elastica;
  const int nv = topo_.vertexCount();
  F.assign(nv, 0.0);
#pragma omp parallel for schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i) {
    if (!roles_.free[i]) continue;
    // Paper sign convention (H = −1/r on an outward sphere): F = −Δ_B H − 2H(H² − K) decreases E.
    F[i] = -lh_[i] - (elastica ? 2 * curv_.Hflow[i] * curv_.g[i] : 0.0);
  }
}

double FlowState::normalStep() {
  const double aMin = checkedMinArea();
  const double tau = opt_.stepFactor * aMin * aMin;  // paper: τ = A_min²/150
  const double eps = opt_.driftFactor * aMin;        // paper: ε = 12 A_min
  speed(speed_);
  if (opt_.tangentialDrift) tangentialDrift(topo_, geo_, mesh_.positions, roles_.free, u_, drift_);
  const int nv = topo_.vertexCount();
  bool finite = true;
#pragma omp parallel for reduction(&& : finite) schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i) {
    if (!roles_.free[i]) continue;
    Vec3& p = mesh_.positions[i];
    p += tau * speed_[i] * geo_.vertexNormal[i];
    if (opt_.tangentialDrift) p += eps * drift_[i];
    finite = finite && p.allFinite();
  }
  if (!finite) throw NumericalError("a vertex position became non-finite");
  return tau;
}

double FlowState::bilaplacianStep() {
  uniformBiUmbrella(topo_, mesh_.positions, roles_.free, u_, drift_);
  const int nv = topo_.vertexCount();
  bool finite = true;
#pragma omp parallel for reduction(&& : finite) schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i) {
    if (!roles_.free[i]) continue;
    mesh_.positions[i] -= opt_.bilaplacianStep * drift_[i];
    finite = finite && mesh_.positions[i].allFinite();
  }
  if (!finite) throw NumericalError("a vertex position became non-finite");
  // U0² ≈ (ℓ⁴/16) Δ², so this step is worth about bilaplacianStep·ℓ⁴/16 of flow time.
  const double ell = geo_.meanEdgeLength;
  return opt_.bilaplacianStep * ell * ell * ell * ell / 16;
}

void FlowState::slideBoundary() {
  if (slider_ && roles_.slidingCount > 0) slider_->slide(topo_, mesh_.positions, roles_.sliding, kSlideRate);
}

bool FlowState::trySemiImplicitStep(double tau) {
  auto reject = [&] {
    mesh_.positions = saved_;
    evaluated_ = false;
    return false;
  };
  evaluate();
  speed(speed_);
  const int nv = topo_.vertexCount(), n = roles_.freeCount;
  if (!solver_) solver_ = std::make_shared<SparseSolver>();

  // (M_ff + τ/2 · C_fa M_aa⁻¹ C_af) δ_f = τ M_ff F_f: to leading order F(P + δN) ≈ F − ½Δ_B²δ,
  // so the stiff fourth-order part is taken at the new time and everything else is lagged.
  auto& trip = solver_->triplets;
  trip.clear();
  std::vector<std::pair<int, double>> column;  // (row, C_ij) of the free vertices around active i
  for (int i = 0; i < nv; ++i) {
    if (!roles_.active[i]) continue;
    column.clear();
    double diagonal = 0;
    for (int k = topo_.ringBegin(i); k < topo_.ringEnd(i); ++k) {
      const double w = geo_.edgeWeight[topo_.ringEdge(k)];
      diagonal -= w;
      const int r = freeIndex_[topo_.ringVertex(k)];
      if (r >= 0) column.emplace_back(r, w);
    }
    if (freeIndex_[i] >= 0) column.emplace_back(freeIndex_[i], diagonal);
    // A vertex without area (degenerate around it) contributes zeros, but its entries stay: the
    // pattern was analysed once and must not change with the geometry (found by fuzzing: a vertex
    // that became regular added entries outside it, and the factorisation wrote past its buffers).
    const double s = geo_.isRegular(i) ? 0.5 * tau / geo_.vertexArea[i] : 0.0;
    for (const auto& [r1, c1] : column)
      for (const auto& [r2, c2] : column) trip.emplace_back(r1, r2, s * c1 * c2);
  }
  Eigen::VectorXd rhs(n);
  for (int v = 0; v < nv; ++v) {
    const int r = freeIndex_[v];
    if (r < 0) continue;
    trip.emplace_back(r, r, geo_.vertexArea[v]);
    rhs[r] = tau * geo_.vertexArea[v] * speed_[v];
  }
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(trip.begin(), trip.end());
  if (!solver_->analysed) {
    solver_->ldlt.analyzePattern(K);  // the pattern depends on the topology only
    solver_->analysed = true;
  }
  solver_->ldlt.factorize(K);
  saved_ = mesh_.positions;
  if (solver_->ldlt.info() != Eigen::Success) return reject();
  const Eigen::VectorXd delta = solver_->ldlt.solve(rhs);

  const double energyBefore = energy_;
  faceNormalBefore_ = geo_.faceNormal;
  for (int v = 0; v < nv; ++v) {
    const int r = freeIndex_[v];
    if (r < 0) continue;
    if (!std::isfinite(delta[r])) return reject();
    double ring = 0;
    for (int k = topo_.ringBegin(v); k < topo_.ringEnd(v); ++k)
      ring += (saved_[topo_.ringVertex(k)] - saved_[v]).norm();
    if (std::abs(delta[r]) > kMaxJump * ring / std::max(1, topo_.valence(v))) return reject();
    mesh_.positions[v] += delta[r] * geo_.vertexNormal[v];
  }
  evaluated_ = false;
  evaluate();
  if (!std::isfinite(energy_)) return reject();
  // The Laplacian-of-H flow is not a descent of E: it is judged by not creating folds only.
  if (opt_.flow == FlowType::Elastica && energy_ > energyBefore * (1 + kEnergySlack) + 1e-12)
    return reject();
  for (int f = 0; f < topo_.faceCount(); ++f)
    if (roles_.activeFace[f] && geo_.faceNormal[f].dot(faceNormalBefore_[f]) < 0) return reject();

  for (int pass = 0; pass < opt_.driftPasses && opt_.tangentialDrift; ++pass) driftPass();
  slideBoundary();
  evaluated_ = false;
  return true;
}

void FlowState::driftPass() {
  evaluate();
  const double eps = opt_.driftFactor * activeMinArea_;
  tangentialDrift(topo_, geo_, mesh_.positions, roles_.free, u_, drift_);
  const int nv = topo_.vertexCount();
#pragma omp parallel for schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i)
    if (roles_.free[i]) mesh_.positions[i] += eps * drift_[i];
  evaluated_ = false;
}

}  // namespace elastica
