// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/bending_energy.h"
#include "support/parallel.h"

#include <unsupported/Eigen/AutoDiff>

#include <algorithm>
#include <cmath>

namespace elastica {
namespace {

// The needle barrier: kBarrierWeight · Σ (cot θ − cot θ₀)² over the corners of moving faces whose
// angle θ is below θ₀ = 10°. Zero on any mesh whose angles are all at least θ₀, so it moves no
// fixed point of W there; it only keeps W from being lowered by needles, where the cotangent
// Laplacian misreads the curvature: without it a 96×32 torus slid its vertices into 1° needles
// and W fell to 64 (8π² ≈ 79 is the least any torus has).
constexpr double kBarrierCot = 5.6712818196177066;  // cot 10°
constexpr double kBarrierWeight = 1;

// The barrier's term at a corner of cotangent `cot` (double or Dual).
template <class T>
T barrier(const T& cot) {
  return cot > kBarrierCot ? T(kBarrierWeight * (cot - kBarrierCot) * (cot - kBarrierCot)) : T(0);
}

}  // namespace

double needleBarrierStiffness(double cot) {
  if (!(cot > kBarrierCot)) return 0;
  // At most a 1° corner's: a scan's own slivers (0.01°) would give 10¹⁶, beyond what a
  // factorisation in double resolves beside the bending terms.
  constexpr double kLargestCot = 57.289961630759;  // cot 1°
  cot = std::min(cot, kLargestCot);
  const double dcot = 1 + cot * cot;  // −d cot / dθ
  return kBarrierWeight * (2 * dcot * dcot + 4 * (cot - kBarrierCot) * cot * dcot);
}

namespace {

using Partials = Eigen::Matrix<double, 9, 1>;
using Dual = Eigen::AutoDiffScalar<Partials>;
using DualVec = Eigen::Matrix<Dual, 3, 1>;

// One face's share of dW for fixed z_k = y_k / A_k (the chain rule of |y|²/A holds z and |z|²
// fixed): Σ_k 2 z_k·y_k^f − |z_k|² A_k^f + w_k θ_k, whose partials in the face's nine coordinates
// are the face's contribution to ∂W/∂X (w_k = 2 where corner k's vertex is counted: −2 K A =
// −2(2π − Σθ)). Forward-mode differentiation of the same formulas computeGeometry() evaluates.
void faceGradient(const Vec3 (&x)[3], const Vec3 (&z)[3], const double (&zz)[3], const double (&w)[3],
                  VertexArea areaType, double* out) {
  DualVec p[3];
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) p[k][c] = Dual(x[k][c], 9, 3 * k + c);
  const DualVec e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};  // e[k] opposite corner k
  const DualVec n = e[2].cross(-e[1]);
  const Dual twiceArea = sqrt(n.squaredNorm());
  const Dual area = 0.5 * twiceArea;
  Dual dot[3], cot[3];
  bool obtuse[3];
  for (int k = 0; k < 3; ++k) {
    dot[k] = -e[(k + 2) % 3].dot(e[(k + 1) % 3]);
    cot[k] = dot[k] / twiceArea;
    obtuse[k] = dot[k].value() < 0;
  }
  Dual f = 0;
  for (int k = 0; k < 3; ++k) f += barrier(cot[k]);
  for (int k = 0; k < 3; ++k) {
    if (w[k] == 0) continue;  // z_k = 0 as well: the vertex carries no term
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    Dual a;
    if (areaType == VertexArea::Barycentric) a = area / 3;
    else if (obtuse[0] || obtuse[1] || obtuse[2]) a = obtuse[k] ? area / 2 : area / 4;
    else a = (e[k1].squaredNorm() * cot[k1] + e[k2].squaredNorm() * cot[k2]) / 8;
    const DualVec y = 0.5 * cot[k2] * (p[k1] - p[k]) + 0.5 * cot[k1] * (p[k2] - p[k]);
    Dual zy = 0;
    for (int c = 0; c < 3; ++c) zy += z[k][c] * y[c];
    f += 2 * zy - zz[k] * a + w[k] * atan2(twiceArea, dot[k]);
  }
  for (int i = 0; i < 9; ++i) out[i] = f.derivatives()[i];
}

}  // namespace

double bendingEnergy(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                     const std::vector<std::uint8_t>& active, BendingEnergy& out) {
  const int nv = topo.vertexCount();
  out.y.resize(nv);
  out.term.assign(nv, 0.0);
  out.value = parallelSum(nv, [&](int i) {
    out.y[i] = Vec3::Zero();
    if (!countedInBending(topo, geo, active, i)) return 0.0;
    Vec3 y = Vec3::Zero();
    for (int k = topo.ringBegin(i); k < topo.ringEnd(i); ++k)
      y += geo.edgeWeight[topo.ringEdge(k)] * (p[topo.ringVertex(k)] - p[i]);
    out.y[i] = y;
    return out.term[i] = y.squaredNorm() / geo.vertexArea[i] - 2 * (2 * M_PI - geo.angleSum[i]);
  });
  // The barrier, over the faces with a counted corner (those bendingGradient differentiates); a
  // third of each face's share goes to each corner's term, for the culprit search.
  const auto& faces = topo.faces();
  for (int f = 0; f < topo.faceCount(); ++f) {
    const Face& t = faces[f];
    if (!(geo.faceArea[f] > 0) || !(countedInBending(topo, geo, active, t[0]) ||
                                     countedInBending(topo, geo, active, t[1]) ||
                                     countedInBending(topo, geo, active, t[2])))
      continue;
    double b = 0;
    for (int k = 0; k < 3; ++k) b += barrier(geo.cornerDot[3 * static_cast<std::size_t>(f) + k] / (2 * geo.faceArea[f]));
    out.value += b;
    if (b > 0)
      for (int v : t) out.term[v] += b / 3;
  }
  return out.value;
}

void bendingGradient(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                     const std::vector<std::uint8_t>& active, BendingEnergy& out) {
  bendingEnergy(topo, geo, p, active, out);
  const int nf = topo.faceCount(), nv = topo.vertexCount();
  const auto& faces = topo.faces();
  out.faceGrad.assign(9 * static_cast<std::size_t>(nf), 0.0);
  parallelFor(nf, [&](int f) {
    const Face& t = faces[f];
    Vec3 x[3], z[3];
    double zz[3], w[3];
    bool any = false;
    for (int k = 0; k < 3; ++k) {
      const int v = t[k];
      x[k] = p[v];
      const bool counted = countedInBending(topo, geo, active, v);
      z[k] = counted ? Vec3(out.y[v] / geo.vertexArea[v]) : Vec3::Zero();
      zz[k] = z[k].squaredNorm();
      w[k] = counted ? 2.0 : 0.0;
      any = any || counted;
    }
    if (any && geo.faceArea[f] > 0) faceGradient(x, z, zz, w, geo.areaType, &out.faceGrad[9 * static_cast<std::size_t>(f)]);
  });
  out.gradient.resize(nv);
  parallelFor(nv, [&](int v) {
    Vec3 g = Vec3::Zero();
    for (int k = topo.cornerBegin(v); k < topo.cornerEnd(v); ++k) {
      const int c = topo.corner(k);
      const double* d = &out.faceGrad[9 * static_cast<std::size_t>(c / 3) + 3 * (c % 3)];
      g += Vec3(d[0], d[1], d[2]);
    }
    out.gradient[v] = g;
  });
}

}  // namespace elastica
