// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/tangential.h"
#include "support/parallel.h"

namespace elastica {
namespace {

// out_i = 1/(2 A_i n_i) Σ_j w_ij (f_j − f_i) at moving vertices, 0 elsewhere (w: per-edge weights).
void areaUmbrella(const Topology& topo, const Geometry& g, const std::vector<double>& w,
                  const std::vector<std::uint8_t>& moving, const std::vector<Vec3>& f, int i, Vec3& out) {
  Vec3 sum = Vec3::Zero();
  const int n = topo.valence(i);
  if (moving[i] && g.ringArea[i] > 0 && n > 0) {
    for (int k = topo.ringBegin(i); k < topo.ringEnd(i); ++k) sum += w[topo.ringEdge(k)] * (f[topo.ringVertex(k)] - f[i]);
    sum /= 2 * g.ringArea[i] * n;
  }
  out = sum;
}

}  // namespace

void tangentialDrift(const Topology& topo, const Geometry& g, const std::vector<Vec3>& p,
                     const std::vector<std::uint8_t>& moving, DriftScratch& scratch, std::vector<Vec3>& t) {
  const int nv = topo.vertexCount(), ne = topo.edgeCount();
  const double lengthFloor = 1e-12 * (g.meanEdgeLength > 0 ? g.meanEdgeLength : 1.0);
  std::vector<double>& w = scratch.weight;
  std::vector<Vec3>& u = scratch.u;
  w.resize(ne);
  u.resize(nv);
  t.resize(nv);
  parallelFor(ne, [&](int e) {
    const auto& oc = topo.edgeOppositeCorners(e);
    const double a = g.faceArea[oc[0] / 3] + (oc[1] >= 0 ? g.faceArea[oc[1] / 3] : 0.0);
    w[e] = g.edgeLength[e] > lengthFloor ? a / g.edgeLength[e] : 0.0;
  });
  parallelFor(nv, [&](int i) { areaUmbrella(topo, g, w, moving, p, i, u[i]); });  // U(P); zero where not moving
  parallelFor(nv, [&](int i) {
    areaUmbrella(topo, g, w, moving, u, i, t[i]);  // U(U(P)) = U²
    const Vec3& n = g.vertexNormal[i];
    t[i] = -(t[i] - t[i].dot(n) * n);
  });
}

void uniformBiUmbrella(const Topology& topo, const std::vector<Vec3>& p, const std::vector<std::uint8_t>& moving,
                       std::vector<Vec3>& u0, std::vector<Vec3>& out) {
  const int nv = topo.vertexCount();
  auto umbrella = [&](const std::vector<Vec3>& f, int i) {
    Vec3 s = Vec3::Zero();
    const int n = topo.valence(i);
    for (int k = topo.ringBegin(i); k < topo.ringEnd(i); ++k) s += f[topo.ringVertex(k)] - f[i];
    return n > 0 ? Vec3(s / n) : s;
  };
  u0.resize(nv);
  out.resize(nv);
  parallelFor(nv, [&](int i) { u0[i] = topo.isBoundaryVertex(i) ? Vec3::Zero() : umbrella(p, i); });
  parallelFor(nv, [&](int i) { out[i] = moving[i] ? umbrella(u0, i) : Vec3::Zero(); });
}

}  // namespace elastica
