// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/resolution_check.h"

#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/errors.h>
#include <elastica/geometry.h>
#include <elastica/subdivision.h>
#include <elastica/topology.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

namespace elastica {
namespace {

// The unresolved vertices: where the rise per unit area is this many times its mean.
constexpr double kConcentration = 2;

// Per-vertex energy terms (4H² − 2K)A of a mesh, and their sum.
std::vector<double> vertexTerms(const Topology& topo, const std::vector<Vec3>& p, const FlowOptions& opt, double& sum) {
  const Geometry geo = computeGeometry(topo, p, opt.area);
  const Curvature c = computeCurvature(topo, geo, p, opt.curvature);
  std::vector<double> terms(topo.vertexCount());
  for (int v = 0; v < topo.vertexCount(); ++v) terms[v] = vertexCurvatureEnergy(topo, geo, c, v);
  sum = totalCurvatureEnergy(topo, geo, c);
  return terms;
}

}  // namespace

double Resolution::gap() const { return (loopEnergy - energy) / std::max(std::abs(energy), 1.0); }

bool measureResolution(const TriMesh& mesh, const FlowOptions& opt, Resolution& out) {
  const int n = mesh.vertexCount();
  const Topology topo(n, mesh.faces);
  if (topo.boundaryEdgeCount() > 0) return false;
  TriMesh fine = mesh;
  try {
    subdivideLoop(fine);
  } catch (const InvalidInputError&) {
    return false;
  }
  const Topology fineTopo(fine.vertexCount(), fine.faces);
  Resolution r;
  const Geometry geo = computeGeometry(topo, mesh.positions, opt.area);
  const std::vector<double> coarse = vertexTerms(topo, mesh.positions, opt, r.energy);
  const std::vector<double> subdivided = vertexTerms(fineTopo, fine.positions, opt, r.loopEnergy);
  // Each coarse vertex owns its own fine vertex and half of each edge vertex around it (an edge
  // vertex's fine neighbours include exactly its coarse edge's two ends).
  std::vector<double> rise(n, 0);
  for (int v = 0; v < n; ++v) rise[v] = subdivided[v] - coarse[v];
  for (int w = n; w < fineTopo.vertexCount(); ++w)
    for (int k = fineTopo.ringBegin(w); k < fineTopo.ringEnd(w); ++k)
      if (fineTopo.ringVertex(k) < n) rise[fineTopo.ringVertex(k)] += 0.5 * subdivided[w];
  // Where the rise per unit area is kConcentration times its mean; if nowhere, the gap is spread
  // over the whole mesh and every vertex is flagged. (A share of the sorted rises, the first rule,
  // drew its line through a sphere's nearly equal rises, where MeshLab's float input and the
  // CLI's double flagged different vertices.)
  double total = 0, area = 0;
  for (int v = 0; v < n; ++v) total += rise[v], area += geo.vertexArea[v];
  const double mean = area > 0 ? total / area : 0;
  r.unresolved.assign(n, 0);
  bool any = false;
  for (int v = 0; v < n; ++v) {
    if (!(geo.vertexArea[v] > 0) || !(rise[v] > kConcentration * mean * geo.vertexArea[v]) || !(mean > 0)) continue;
    any = true;
    r.unresolved[v] = 1;
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) r.unresolved[topo.ringVertex(k)] = 1;
  }
  if (!any) r.unresolved.assign(n, 1);
  out = std::move(r);
  return true;
}

}  // namespace elastica
