// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/working_set.h"

namespace elastica {

std::size_t explicitStepWorkingSetBytes(FlowState& state, const ExplicitIntegrator& integrator) {
  auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  const Geometry& geo = state.geometry();
  const Curvature& curv = state.curvature();
  const VertexRoles& roles = state.roles();
  return state.topology().byteSize() + bytes(state.mesh().positions) + bytes(roles.free) + bytes(roles.active) +
         bytes(roles.activeFace) + bytes(geo.faceArea) + bytes(geo.faceNormal) + bytes(geo.cornerDot) +
         bytes(geo.cornerCot) + bytes(geo.cornerArea) + bytes(geo.edgeLength) + bytes(geo.edgeWeight) +
         bytes(geo.vertexArea) + bytes(geo.ringArea) + bytes(geo.vertexNormal) + bytes(geo.angleSum) +
         bytes(curv.H) + bytes(curv.K) + bytes(curv.Hflow) + bytes(curv.g) + bytes(state.laplacianOfPositions()) +
         integrator.scratchBytes();
}

}  // namespace elastica
