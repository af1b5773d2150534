// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/curvature.h>
#include <elastica/laplacian.h>
#include "support/parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace elastica {

void computeCurvature(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                      const CurvatureOptions& opt, Curvature& out, std::vector<Vec3>& lp,
                      const std::vector<std::uint8_t>* active) {
  const int nv = topo.vertexCount();
  cotanLaplacian(topo, geo, p, lp);
  out.H.resize(nv);
  out.K.resize(nv);
  out.Hflow.resize(nv);
  out.g.resize(nv);

  const bool paperLambda = opt.h2k == H2KTreatment::PaperLambda;
  auto add = [](std::size_t& a, std::size_t b) { a += b; };
  // H and K; with the clamp (default) also the flow's H and g, in the same pass.
  std::size_t clamped = parallelReduce(nv, std::size_t{0}, [&](int i, std::size_t& clampedHere) {
    double h = 0, k = 0;
    if (geo.isRegular(i)) {
      // Δ_B P = 2H N (Meyer's normalisation): H = ½ N·Δ_B P.
      h = 0.5 * geo.vertexNormal[i].dot(lp[i]);
      // A boundary vertex's full angle is π, an interior vertex's 2π.
      const double full = topo.isBoundaryVertex(i) ? M_PI : 2 * M_PI;
      k = (full - geo.angleSum[i]) / geo.vertexArea[i];
    }
    out.H[i] = h;
    out.K[i] = k;
    if (paperLambda) return;
    const double g = h * h - k;
    out.Hflow[i] = h;
    out.g[i] = std::max(g, 0.0);
    if (g < 0) ++clampedHere;
  }, add);
  out.lambda = 1;
  out.lambdaVertices = 0;
  out.clampedVertices = clamped;
  if (!paperLambda) return;

  // The paper's λ rule, with guards (see H2KTreatment::PaperLambda): D is the set of active
  // interior vertices with H ≠ 0, H² < K and K above the scale-relative floor. (At a boundary
  // vertex K holds the boundary's turning angle, not a Gaussian curvature.)
  const double ell = geo.meanEdgeLength > 0 ? geo.meanEdgeLength : 1.0;
  const double kFloor = opt.relativeKFloor / (ell * ell);
  auto inD = [&](int i) {
    const double h = out.H[i], k = out.K[i];
    return (!active || (*active)[i]) && !topo.isBoundaryVertex(i) && h != 0 && k > kFloor && h * h < k;
  };
  double lambda = std::numeric_limits<double>::infinity();
  for (int i = 0; i < nv; ++i) {
    if (!inD(i)) continue;
    lambda = std::min(lambda, std::abs(out.H[i]) / std::sqrt(out.K[i]));
    ++out.lambdaVertices;
  }
  if (out.lambdaVertices > 0) out.lambda = std::max(lambda, opt.lambdaFloor);

  out.clampedVertices = parallelReduce(nv, std::size_t{0}, [&](int i, std::size_t& clampedHere) {
    const double h = inD(i) ? out.H[i] / out.lambda : out.H[i];
    const double g = h * h - out.K[i];
    out.Hflow[i] = h;
    out.g[i] = std::max(g, 0.0);
    if (g < 0) ++clampedHere;
  }, add);
}

Curvature computeCurvature(const Topology& topo, const Geometry& geo, const std::vector<Vec3>& p,
                           const CurvatureOptions& opt) {
  Curvature c;
  std::vector<Vec3> lp;
  computeCurvature(topo, geo, p, opt, c, lp);
  return c;
}

}  // namespace elastica
