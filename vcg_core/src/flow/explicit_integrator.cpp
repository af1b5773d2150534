// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/laplacian.h>
#include "flow/explicit_integrator.h"
#include "flow/flow_speed.h"
#include "support/parallel.h"

namespace elastica {

double ExplicitIntegrator::step(FlowState& state) {
  state.evaluate();
  const double dt = state.options().flow == FlowType::Bilaplacian ? bilaplacianStep(state) : normalStep(state);
  state.invalidate();
  state.slideBoundary();
  return dt;
}

double ExplicitIntegrator::normalStep(FlowState& state) {
  const FlowOptions& opt = state.options();
  const double aMin = state.checkedMinArea();
  const double tau = opt.stepFactor * aMin * aMin;  // paper: τ = A_min²/150
  const double eps = opt.driftFactor * aMin;        // paper: ε = 12 A_min
  const Topology& topo = state.topology();
  const Geometry& geo = state.geometry();
  const Curvature& curv = state.curvature();
  const std::vector<std::uint8_t>& free = state.roles().free;
  std::vector<Vec3>& positions = state.positions();
  cotanLaplacian(topo, geo, curv.Hflow, lh_);
  const bool drift = opt.tangentialDrift;
  if (drift) tangentialDrift(topo, geo, positions, free, driftScratch_, drift_);
  const bool elastica = opt.flow == FlowType::Elastica;
  const int nv = topo.vertexCount();
  const int nonFinite = parallelReduce(nv, 0, [&](int i, int& bad) {
    if (!free[i]) return;
    const double F = normalSpeed(elastica, lh_[i], curv.Hflow[i], curv.g[i]);
    Vec3& p = positions[i];
    p += tau * F * geo.vertexNormal[i];
    if (drift) p += eps * drift_[i];
    bad += !p.allFinite();
  }, [](int& a, int b) { a += b; });
  if (nonFinite > 0) throw NumericalError("a vertex position became non-finite");
  return tau;
}

double ExplicitIntegrator::bilaplacianStep(FlowState& state) {
  const double stepSize = state.options().bilaplacianStep;
  const std::vector<std::uint8_t>& free = state.roles().free;
  std::vector<Vec3>& positions = state.positions();
  uniformBiUmbrella(state.topology(), positions, free, u_, drift_);
  const int nv = state.topology().vertexCount();
  const int nonFinite = parallelReduce(nv, 0, [&](int i, int& bad) {
    if (!free[i]) return;
    positions[i] -= stepSize * drift_[i];
    bad += !positions[i].allFinite();
  }, [](int& a, int b) { a += b; });
  if (nonFinite > 0) throw NumericalError("a vertex position became non-finite");
  // U0² ≈ (ℓ⁴/16) Δ², so this step is worth about bilaplacianStep·ℓ⁴/16 of flow time.
  const double ell = state.geometry().meanEdgeLength;
  return stepSize * ell * ell * ell * ell / 16;
}

std::size_t ExplicitIntegrator::scratchBytes() const {
  auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  return bytes(lh_) + bytes(driftScratch_.weight) + bytes(driftScratch_.u) + bytes(drift_);
}

}  // namespace elastica
