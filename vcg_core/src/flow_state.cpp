#include <elastica/energy.h>
#include <elastica/parallel.h>
#include <elastica/errors.h>
#include <elastica/flow_state.h>
#include <elastica/laplacian.h>
#include <elastica/tangential.h>

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
                     BoundarySlider* slider)
    : mesh_(std::move(mesh)),
      opt_(opt),
      topo_(mesh_.vertexCount(), mesh_.faces),
      roles_(assignRoles(topo_, &faceSelected, opt.boundary)),
      slider_(slider) {
  if (slider_ && roles_.slidingCount > 0) slider_->attach(topo_, mesh_.positions, roles_.sliding);
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

double FlowState::normalStep() {
  const double aMin = checkedMinArea();
  const double tau = opt_.stepFactor * aMin * aMin;  // paper: τ = A_min²/150
  const double eps = opt_.driftFactor * aMin;        // paper: ε = 12 A_min
  cotanLaplacian(topo_, geo_, curv_.Hflow, lh_);
  if (opt_.tangentialDrift) tangentialDrift(topo_, geo_, mesh_.positions, roles_.free, u_, drift_);
  const bool elastica = opt_.flow == FlowType::Elastica;
  const int nv = topo_.vertexCount();
  bool finite = true;
#pragma omp parallel for reduction(&& : finite) schedule(static) if (nv > kParallelGrain)
  for (int i = 0; i < nv; ++i) {
    if (!roles_.free[i]) continue;
    // Paper sign convention (H = −1/r on an outward sphere): F = −Δ_B H − 2H(H² − K) decreases E.
    double F = -lh_[i];
    if (elastica) F -= 2 * curv_.Hflow[i] * curv_.g[i];
    Vec3& p = mesh_.positions[i];
    p += tau * F * geo_.vertexNormal[i];
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

}  // namespace elastica
