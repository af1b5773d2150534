// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/mesh_quality_stage.h"
#include "flow/constraints.h"
#include "flow/region_guard.h"
#include "mesh/self_intersection.h"
#include "mesh/patch_remeshing.h"
#include "mesh/surface_projection.h"
#include "mesh/thickness.h"

#include <elastica/geometry.h>
#include <elastica/mesh_curvature.h>
#include <elastica/mesh_quality.h>
#include <elastica/subdivision.h>
#include <elastica/topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace elastica {
namespace {

// Whether two vertices of the flagged faces sit at one point.
bool stacksVertices(const TriMesh& mesh, const std::vector<std::uint8_t>& faces) {
  std::vector<std::array<double, 3>> points;
  std::vector<std::uint8_t> seen(mesh.positions.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (faces[f])
      for (int v : mesh.faces[f])
        if (!seen[v]++) points.push_back({mesh.positions[v].x(), mesh.positions[v].y(), mesh.positions[v].z()});
  std::sort(points.begin(), points.end());
  return std::adjacent_find(points.begin(), points.end()) != points.end();
}

// coarseStart(): the coarse start's level has at least this many vertices, where a step
// costs about 0.1 s (not tuned further): a large mesh reaches its shape sooner from there than at
// full size (docs/decisions.md, "The schedule's rules": the coarse start).
constexpr long long kCoarseStartVertices = 10000;
// The floor for a whole mesh with a border, counted on its moving vertices (coarseStart): there
// the border's fixed rows keep the input's triangles, and the moving ones are remeshed at the
// input's mean face area (set on one open scan: docs/decisions.md, "The schedule's rules": the
// coarse start).
constexpr double kCoarseStartBorderedVertices = 2500;
// workingResolutionFloor(): free vertices per handle, and without handles (see the header).
constexpr int kFloorVerticesPerHandle = 1000, kFloorVertices = 100;

// Curvature-adaptive remeshing aims at κ·ℓ = 0.4, below the 0.6 above which the discrete energy
// of a cage's flow was seen to fall below the continuum's (docs/figures.md), and refines at most
// 8× below the region's mean edge length.
constexpr double kTargetCurvatureTimesEdge = 0.4, kMaxRefinement = 8;
// remeshMovingRegion's `refineAt`: edges this fraction of their length around the flagged vertices
// (and no shorter than half the curvature's shortest).
constexpr double kUnresolvedRefinement = 0.5;
constexpr int kMaxGrowth = 8;  // a remeshing leaves at most 8× the vertices (+1000)
constexpr int kMaxSplitGrowth = 64, kMaxSplitExtra = 2000;  // splitLongEdges' bound, the same way
constexpr double kMaxEdgeToTarget = 1000;
// remeshMovingRegion within a budget: fits of the targets after the first, before giving up.
constexpr int kBudgetAttempts = 2;
// remeshMovingRegion's `crossingRefinements`: the targets within this many target edge lengths of
// a face the remeshing made cross are halved for the next try.
constexpr double kCrossingReach = 3;
// A flowed mesh needs remeshing below this angle or above this κℓ (needsRemeshing).
constexpr double kRemeshAngleDegrees = 20, kRemeshCurvatureTimesEdge = 0.6;
// cadWorkingEdgeLength(): edges across the thinnest feature, the area fraction of the surface
// thinner than the feature that decides (one sliver or chamfer does not).
constexpr double kEdgesAcrossThinnest = 3, kThinnestQuantile = 0.1;
// isotropicEdgeMissesThinnest(): an isotropic edge this many times the thinnest feature steps over
// it, and the shape it leaves is too coarse (docs/decisions.md, "CAD parts").
constexpr double kIsotropicOverThinnest = 2;
// remeshOnSurface(): a CAD part's sharp edges, where its faces' normals differ by more than this (a
// box's 90° edges, a thin wall's rim; not the few degrees between a tessellated cylinder's facets).
constexpr double kSharpEdgeDegrees = 60;

// Faces whose three vertices are all free: the region a remeshing may rewrite.
std::vector<std::uint8_t> movingFaces(const TriMesh& mesh, const VertexRoles& roles) {
  std::vector<std::uint8_t> region(mesh.faces.size(), 0);
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Face& t = mesh.faces[f];
    region[f] = roles.free[t[0]] && roles.free[t[1]] && roles.free[t[2]];
  }
  return region;
}

// The median area of the faces flagged in `region` (all faces if empty), 0 if there are none; the
// isotropic remeshing's size (remeshMovingRegion) and the coarse start's count (coarseStart)
// both come from it. `total` (optional) receives the flagged faces' summed area.
double medianFaceArea(const TriMesh& mesh, const std::vector<std::uint8_t>& region, double* total = nullptr) {
  std::vector<double> areas;
  areas.reserve(mesh.faces.size());
  double sum = 0;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (!region.empty() && !region[f]) continue;
    const Face& t = mesh.faces[f];
    areas.push_back(0.5 * (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).norm());
    sum += areas.back();
  }
  if (total) *total = sum;
  if (areas.empty()) return 0;
  std::nth_element(areas.begin(), areas.begin() + areas.size() / 2, areas.end());
  return areas[areas.size() / 2];
}

// The edge of an equilateral triangle of the flagged faces' median area, sqrt(4A / √3): the
// isotropic remeshing's target (the mean would follow a refined neck down).
double equilateralEdge(const TriMesh& mesh, const std::vector<std::uint8_t>& region) {
  return std::sqrt(4 * medianFaceArea(mesh, region) / std::sqrt(3.0));
}

// Whether a flagged face has an edge kMaxEdgeToTarget times `target` or longer (or not finite):
// not a surface to remesh but a vertex thrown far away (fuzzing found one that made the remesher
// split for minutes). Such a mesh is left to the flow, which refuses or repairs it step by step.
bool hasFarVertex(const TriMesh& mesh, const std::vector<std::uint8_t>& region, double target) {
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (!region[f]) continue;
    const Face& t = mesh.faces[f];
    for (int k = 0; k < 3; ++k)
      if (!((mesh.positions[t[k]] - mesh.positions[t[(k + 1) % 3]]).norm() <= kMaxEdgeToTarget * target)) return true;
  }
  return false;
}

// H and K of the region's mesh as measureCurvature() gives them (its default options), on the
// region's topology instead of a new one. H in the flow's sign: the callers read only |H| and H²,
// which the reported sign (its negation) leaves bit for bit the same.
Curvature curvatureOf(const MovingRegion& region) {
  const CurvatureMeasureOptions defaults;
  const Geometry geo = computeGeometry(region.topology(), region.mesh().positions, defaults.area);
  return computeCurvature(region.topology(), geo, region.mesh().positions, defaults.curvature);
}

// The vertices a remeshing toward `sigma` leaves on the flagged faces: two faces a vertex, each
// face an equilateral triangle of its corners' mean target.
double predictedVertices(const TriMesh& mesh, const std::vector<std::uint8_t>& region, const std::vector<double>& sigma,
                         double floor) {
  double count = 0;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (!region[f]) continue;
    const Face& t = mesh.faces[f];
    const Vec3& a = mesh.positions[t[0]];
    const double area = 0.5 * (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a).norm();
    const double s = std::max((sigma[t[0]] + sigma[t[1]] + sigma[t[2]]) / 3, floor);
    count += 0.5 * area / (0.4330127018922193 * s * s);
  }
  return count;
}

// Raises the shortest targets to one floor, the lowest that leaves at most `maxMoving` vertices
// (predictedVertices), by bisection on the floor between the shortest and the longest target.
void fitTargets(const TriMesh& mesh, const std::vector<std::uint8_t>& region, std::vector<double>& sigma,
                double maxMoving) {
  double lo = *std::min_element(sigma.begin(), sigma.end()), hi = *std::max_element(sigma.begin(), sigma.end());
  if (predictedVertices(mesh, region, sigma, lo) <= maxMoving) return;
  if (predictedVertices(mesh, region, sigma, hi) > maxMoving) {
    hi *= std::sqrt(predictedVertices(mesh, region, sigma, hi) / maxMoving);  // coarser than uniform
  }
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    (predictedVertices(mesh, region, sigma, mid) > maxMoving ? lo : hi) = mid;
  }
  for (double& s : sigma) s = std::max(s, hi);
}

// Gives the region a rewritten mesh whose faces flagged in `region` replaced the moving faces:
// faces outside keep their slots on a selection (remeshRegion refills dead slots from the end only
// while no face outside the region would move; a whole mesh's faces may move down, keeping their
// order, and it has no unselected face); the rewritten faces are selected.
bool adopt(MovingRegion& moving, TriMesh&& rewritten, const std::vector<std::uint8_t>& region) {
  return moving.edit([&](TriMesh& out, std::vector<std::uint8_t>& selection) {
    if (!selection.empty()) {
      std::vector<std::uint8_t> next(rewritten.faces.size(), 1);
      for (std::size_t f = 0; f < next.size(); ++f)
        if (!region[f]) next[f] = selection[f];
      selection.swap(next);
    }
    out = std::move(rewritten);
    return true;
  });
}

// remeshMovingRegion's crossing refinement: the targets of `mesh`'s vertices within `reach` of a
// face of `remeshed` that crosses another are halved.
void halveTargetsNearCrossings(const TriMesh& mesh, const TriMesh& remeshed, double reach, std::vector<double>& sigma) {
  std::vector<Vec3> centres;
  for (int f : selfIntersectingFaces(remeshed, nullptr)) {
    const Face& t = remeshed.faces[f];
    centres.push_back((remeshed.positions[t[0]] + remeshed.positions[t[1]] + remeshed.positions[t[2]]) / 3);
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
    for (const Vec3& c : centres)
      if ((mesh.positions[v] - c).norm() <= reach) {
        sigma[v] *= 0.5;
        break;
      }
}

// The moving faces a remeshing can reshape. On a whole mesh with fixed vertices (a border's two
// rows), not the ones at a vertex next to a fixed one: remeshRegion edits no edge of a face
// outside the moving region, and the flow's tangential moves leave thin faces along the fixed rows
// that no remeshing takes away, and reflows for them did not lower the energy (docs/decisions.md, "Regions"). A selection
// keeps every moving face: its runs were measured so.
std::vector<std::uint8_t> reshapableFaces(const MovingRegion& region) {
  const TriMesh& mesh = region.mesh();
  std::vector<std::uint8_t> faces = movingFaces(mesh, region.roles());
  if (!region.selection().empty() || region.roles().freeCount == mesh.vertexCount()) return faces;
  const Topology& topo = region.topology();
  const std::vector<std::uint8_t>& free = region.roles().free;
  std::vector<std::uint8_t> nextToFixed(mesh.positions.size(), 0);
  for (int v = 0; v < topo.vertexCount(); ++v)
    for (int r = topo.ringBegin(v); r < topo.ringEnd(v) && !nextToFixed[v]; ++r) nextToFixed[v] = !free[topo.ringVertex(r)];
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Face& t = mesh.faces[f];
    if (nextToFixed[t[0]] || nextToFixed[t[1]] || nextToFixed[t[2]]) faces[f] = 0;
  }
  return faces;
}

// Whether a region is a selection: some face of its mesh is not selected.
bool isSelection(const MovingRegion& region) {
  const std::vector<std::uint8_t>& selection = region.selection();
  return std::find(selection.begin(), selection.end(), 0) != selection.end();
}

}  // namespace

int closedGenus(const Topology& topo) {
  if (topo.boundaryEdgeCount() > 0) return 0;
  int used = 0;
  for (int v = 0; v < topo.vertexCount(); ++v) used += !topo.isIsolatedVertex(v);
  return std::max(0, (2 - (used - topo.edgeCount() + topo.faceCount())) / 2);
}

CoarseStart coarseStart(const MovingRegion& region) {
  CoarseStart start;
  // A selection starts where it is: its coarse remeshing met the scan's other parts (a 50,000-face
  // region of a leg crossed the foot beside it, and its steps were refused; docs/decisions.md, "Regions").
  if (isSelection(region)) return start;
  start.onMovingFaces = region.topology().boundaryEdgeCount() > 0;
  // A whole closed mesh counts the vertices the isotropic remeshing would give at its own size
  // (remeshMovingRegion: faces of the median area, two faces a vertex), not the input's: a scan of
  // big and small triangles has many more (the bull, midpoint-subdivided twice to 99,000 vertices:
  // about 250,000). A mesh with a border counts its moving faces, the ones its remeshing rewrites,
  // at their mean area: its finest level then has about the vertices it came with, where the
  // median's size tripled a scan of mixed triangles (mannequin-devil: 12,977 to 43,784).
  const std::vector<std::uint8_t> moving =
      start.onMovingFaces ? movingFaces(region.mesh(), region.roles()) : std::vector<std::uint8_t>{};
  double total = 0;
  const double median = medianFaceArea(region.mesh(), moving, &total);
  if (!(median > 0) || !std::isfinite(total)) return start;
  const double area =
      start.onMovingFaces ? total / static_cast<double>(std::count(moving.begin(), moving.end(), 1)) : median;
  const double floor = start.onMovingFaces ? kCoarseStartBorderedVertices : kCoarseStartVertices;
  for (double n = 0.5 * total / area; n >= 4.0 * floor; n /= 4) ++start.levels;
  start.coarsening = std::ldexp(std::sqrt(area / median), start.levels);
  return start;
}

void subdivideMovingFaces(MovingRegion& region) {
  std::vector<std::uint8_t> moving = movingFaces(region.mesh(), region.roles());
  region.edit([&](TriMesh& mesh, std::vector<std::uint8_t>& selection) {
    subdivideLoopRegion(mesh, moving);
    // Every face split has a moving vertex, so it was selected, and so are its appended children.
    if (!selection.empty()) selection.resize(mesh.faces.size(), 1);
    return true;
  });
}

int workingResolutionFloor(const MovingRegion& region) {
  return kFloorVertices + kFloorVerticesPerHandle * closedGenus(region.topology());
}

void subdivideOneLevel(MovingRegion& region) {
  region.edit([](TriMesh& mesh, std::vector<std::uint8_t>& selection) {
    if (selection.empty())
      subdivideMidpoint(mesh);
    else
      subdivideMidpointRegion(mesh, selection);
    return true;
  });
}

int subdivideToWorkingResolution(MovingRegion& region, const FlowOptions& opt) {
  const int floor = workingResolutionFloor(region);
  int levels = 0;
  while (levels < opt.subdivisionLevels && region.roles().freeCount < floor &&
         (opt.targetEdgeLength <= 0 || meanEdgeLength(region.topology(), region.mesh().positions) > opt.targetEdgeLength)) {
    subdivideOneLevel(region);
    ++levels;
  }
  return levels;
}

bool needsRemeshing(const MovingRegion& region) {
  const double smallest = smallestAngleDegrees(region.mesh(), reshapableFaces(region));
  return smallest < kRemeshAngleDegrees || largestMovingCurvatureTimesEdge(region) > kRemeshCurvatureTimesEdge;
}

double smallestMovingAngle(const MovingRegion& region) {
  return smallestAngleDegrees(region.mesh(), movingFaces(region.mesh(), region.roles()));
}

double largestCurvatureTimesEdge(const Topology& topo, const std::vector<Vec3>& positions, const std::vector<double>& H,
                                 const std::vector<double>& K, const std::vector<std::uint8_t>& moving) {
  double largest = 0;
  for (int v = 0; v < topo.vertexCount(); ++v) {
    if (!moving[v] || topo.valence(v) == 0) continue;
    double ell = 0;
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) ell += (positions[topo.ringVertex(k)] - positions[v]).norm();
    const double kappa = std::abs(H[v]) + std::sqrt(std::max(H[v] * H[v] - K[v], 0.0));
    largest = std::max(largest, kappa * ell / topo.valence(v));
  }
  return largest;
}

double largestMovingCurvatureTimesEdge(const MovingRegion& region) {
  const Curvature c = curvatureOf(region);
  return largestCurvatureTimesEdge(region.topology(), region.mesh().positions, c.H, c.K, region.roles().free);
}

std::vector<double> largestPrincipalCurvature(const MovingRegion& region) {
  const Curvature c = curvatureOf(region);
  std::vector<double> kappa(region.mesh().positions.size(), 0);
  for (std::size_t v = 0; v < kappa.size(); ++v)
    kappa[v] = std::abs(c.H[v]) + std::sqrt(std::max(c.H[v] * c.H[v] - c.K[v], 0.0));
  return kappa;
}

bool splitLongEdges(MovingRegion& moving) {
  const TriMesh& mesh = moving.mesh();
  std::vector<std::uint8_t> region = movingFaces(mesh, moving.roles());
  const double target = equilateralEdge(mesh, region);
  if (!(target > 0) || hasFarVertex(mesh, region, target)) return false;
  TriMesh split = mesh;
  std::vector<std::uint8_t> none(mesh.positions.size(), 0);  // no vertex of the input moves
  std::vector<double> sigma(mesh.positions.size(), target);
  PatchRemeshingOptions options;
  options.iterations = 1;
  options.relaxPasses = 0;
  // A split the bound stops is not made: a torus of 40 vertices with one thrown 256 edges away (a
  // fuzzed input) was split to about 30,000, and its remeshings then ran for minutes, before the
  // flow could check its time limit. CAD parts peak far below the bound before their short edges
  // collapse (joint 29x, anchor 22x, rotor 14x).
  options.maxVertices = kMaxSplitGrowth * mesh.vertexCount() + kMaxSplitExtra;
  options.deadline = moving.deadline();
  if (!remeshRegion(split, region, sigma, none, options) || moving.pastDeadline()) return false;
  if (split.vertexCount() == mesh.vertexCount()) return false;
  if (!selfIntersects(mesh) && selfIntersects(split)) return false;
  return adopt(moving, std::move(split), region);
}

bool remeshOnSurface(MovingRegion& moving, double edge) {
  const TriMesh& mesh = moving.mesh();
  if (!(edge > 0) || !moving.selection().empty() || moving.topology().boundaryEdgeCount() > 0) return false;
  std::vector<std::uint8_t> region = movingFaces(mesh, moving.roles());
  if (hasFarVertex(mesh, region, edge)) return false;
  const SurfaceProjector surface(mesh, kSharpEdgeDegrees);
  TriMesh remeshed = mesh;
  std::vector<double> sigma(mesh.positions.size(), edge);
  std::vector<std::uint8_t> movable = moving.roles().free;
  PatchRemeshingOptions options;
  options.surface = &surface;
  options.regionMayShrink = true;
  options.maxVertices = kMaxSplitGrowth * mesh.vertexCount() + kMaxSplitExtra;  // splitLongEdges' bound
  options.deadline = moving.deadline();
  remeshRegion(remeshed, region, sigma, movable, options);
  if (moving.pastDeadline()) return false;
  if (remeshed.vertexCount() == 0 || stacksVertices(remeshed, region)) return false;
  if (!selfIntersects(mesh) && selfIntersects(remeshed)) return false;
  return adopt(moving, std::move(remeshed), region);
}

double isotropicTargetEdge(const MovingRegion& moving) {
  const TriMesh& mesh = moving.mesh();
  return equilateralEdge(mesh, movingFaces(mesh, moving.roles()));
}

namespace {

// The part's thinnest feature (thinnestFeature at kThinnestQuantile) on a whole closed mesh; 0 on a
// selection, a mesh with a boundary, or one whose thickness cannot be measured.
double partThinnest(const MovingRegion& moving) {
  if (!moving.selection().empty() || moving.topology().boundaryEdgeCount() > 0) return 0;
  const double thinnest = thinnestFeature(moving.mesh(), kThinnestQuantile);
  return thinnest > 0 && std::isfinite(thinnest) ? thinnest : 0;
}

}  // namespace

bool isotropicEdgeMissesThinnest(const MovingRegion& moving) {
  const double thinnest = partThinnest(moving);
  return thinnest > 0 && isotropicTargetEdge(moving) > kIsotropicOverThinnest * thinnest;
}

double cadWorkingEdgeLength(const MovingRegion& moving) {
  const double thinnest = partThinnest(moving);
  if (thinnest == 0) return 0;
  const TriMesh& mesh = moving.mesh();
  double area = 0;
  medianFaceArea(mesh, movingFaces(mesh, moving.roles()), &area);
  // An equilateral mesh of edge h has about 2A / (√3 h²) vertices on area A.
  const long long budget = vertexBudget(moving.roles().freeCount, closedGenus(moving.topology()));
  const double finest = std::sqrt(2 * area / (std::sqrt(3.0) * static_cast<double>(budget)));
  return std::max(thinnest / kEdgesAcrossThinnest, finest);
}

long long vertexBudget(long long moving, int genus) {
  constexpr double kVerticesPerEnergy = 1 / (kTargetCurvatureTimesEdge * kTargetCurvatureTimesEdge * 0.8660254037844386);
  constexpr double kWidening = 4;
  return moving + static_cast<long long>(std::ceil(kWidening * kVerticesPerEnergy * 8 * M_PI * (genus + 3)));
}

namespace {

// The remeshing's target edge length per vertex: `target`, where the surface bends within a few
// edges held to kTargetCurvatureTimesEdge / κ (curvatureAdaptive), and shorter at `refineAt`.
std::vector<double> remeshTargets(const MovingRegion& moving, double target, bool curvatureAdaptive,
                                  const std::vector<std::uint8_t>* refineAt) {
  const Topology& topo = moving.topology();
  const TriMesh& mesh = moving.mesh();
  std::vector<double> sigma(mesh.positions.size(), target);
  if (curvatureAdaptive) {
    // Where the surface bends within a few edges (a neck, a tight handle), the discrete energy
    // underestimates what bending costs: edges there are held to kMaxCurvatureTimesEdge / κ,
    // κ the largest principal curvature over the vertex's one-ring (so both sides of a neck agree).
    const std::vector<double> kappa = largestPrincipalCurvature(moving);
    for (int v = 0; v < topo.vertexCount(); ++v) {
      double k = kappa[v];
      for (int r = topo.ringBegin(v); r < topo.ringEnd(v); ++r) k = std::max(k, kappa[topo.ringVertex(r)]);
      if (k > 0) sigma[v] = std::clamp(kTargetCurvatureTimesEdge / k, target / kMaxRefinement, target);
    }
  }
  if (refineAt) {
    for (int v = 0; v < topo.vertexCount(); ++v) {
      if (!(*refineAt)[v] || topo.valence(v) == 0) continue;
      double ell = 0;
      for (int r = topo.ringBegin(v); r < topo.ringEnd(v); ++r) ell += (mesh.positions[topo.ringVertex(r)] - mesh.positions[v]).norm();
      sigma[v] = std::min(sigma[v], std::max(kUnresolvedRefinement * ell / topo.valence(v), target / (2 * kMaxRefinement)));
    }
  }
  return sigma;
}

// Within `maxMoving`: the targets are fitted to it (fitTargets), and fitted again to a smaller
// count in proportion where the remeshing left more than it predicted; false where it still leaves
// more (or the deadline passed): the remeshing is not made.
bool remeshWithinBudget(const MovingRegion& moving, const std::vector<std::uint8_t>& region, const std::vector<double>& sigma,
                        long long maxMoving, const PatchRemeshingOptions& options, TriMesh& remeshed,
                        std::vector<std::uint8_t>& remeshedRegion) {
  const TriMesh& mesh = moving.mesh();
  const long long fixed = mesh.vertexCount() - moving.roles().freeCount;
  double aim = static_cast<double>(maxMoving);
  for (int attempt = 0;; ++attempt) {
    std::vector<double> fitted = sigma;
    if (maxMoving > 0) fitTargets(mesh, region, fitted, aim);
    remeshed = mesh;
    remeshedRegion = region;
    std::vector<std::uint8_t> movable = moving.roles().free;
    remeshRegion(remeshed, remeshedRegion, fitted, movable, options);
    if (moving.pastDeadline()) return false;
    const long long left = remeshed.vertexCount() - fixed;
    if (maxMoving <= 0 || left <= maxMoving) return true;
    if (attempt == kBudgetAttempts) return false;
    aim *= static_cast<double>(maxMoving) / left;
  }
}

// Whether a remeshing (`remeshed`, its region's flags `region`; `before` the flags on the input)
// folded the surface: vertices stacked at one point, or on a selection a face folded flat.
bool remeshingFolds(const MovingRegion& moving, const TriMesh& remeshed, const std::vector<std::uint8_t>& region,
                    const std::vector<std::uint8_t>& before) {
  // A remeshing that stacks vertices at one point is undone, also where the mesh crossed itself
  // before and the crossing test cannot judge it (a noisy region of the lion's head scan: the
  // adaptive remeshing left 49 vertices at one point and the next stage's energy at 4,000 times
  // the last). Comparing the crossing counts instead undid the cow's first remeshing (its input
  // crosses at 137 faces), which then never became round.
  if (stacksVertices(remeshed, region)) return true;
  // A remeshing of a selection that leaves a face folded flat (a corner under
  // kDegenerateAngleDegrees, and below the region's own smallest corner before) is undone: the
  // isotropic remeshing of a 10,000-face region of a scan that crosses itself there (man.off: 253
  // of its faces cross; mannequin-devil: 293) left corners of 4e-14° and 1e-12°, on which the flow's
  // matrices are not positive definite and every attempt of both schemes was refused (36 and 144
  // attempts, then `unchanged`); the curvature-adaptive remeshing of the mannequin's region after
  // its first stage left 0.0064° (from 9.7°) and the region's energy 78.5 → 531, and the run never
  // got back below it; the first remeshings of small regions stay far above the limit
  // (docs/decisions.md, "Regions"). Whole meshes are left as they were.
  constexpr double kDegenerateAngleDegrees = 0.1;
  if (moving.selection().empty()) return false;
  const double after = smallestAngleDegrees(remeshed, region);
  return after < kDegenerateAngleDegrees && after < smallestAngleDegrees(moving.mesh(), before);
}

// Where crossings cannot judge it (a noisy region crossing itself), a remeshing that leaves the
// region's energy kRemeshBlowUp times its value is a folded surface, not a resampled one: the
// devil mannequin's noisy region 1 went from E 883 to 207,260, and every step after was refused.
bool remeshingBlewUp(const TriMesh& mesh, const std::vector<std::uint8_t>& before, const TriMesh& remeshed,
                     const std::vector<std::uint8_t>& region) {
  constexpr double kRemeshBlowUp = 10;
  FlowOptions measure;
  const double energyBefore = regionEnergy(mesh, before, measure), energyAfter = regionEnergy(remeshed, region, measure);
  return !(energyAfter <= kRemeshBlowUp * std::max(std::abs(energyBefore), 1.0));
}

}  // namespace

bool remeshMovingRegion(MovingRegion& moving, bool curvatureAdaptive, double coarsening, long long maxMoving,
                        const std::vector<std::uint8_t>* refineAt, int crossingRefinements, bool onSurface) {
  const TriMesh& mesh = moving.mesh();
  std::vector<std::uint8_t> region = movingFaces(mesh, moving.roles());
  const double target = coarsening * equilateralEdge(mesh, region);
  if (!(target > 0) || hasFarVertex(mesh, region, target)) return false;

  // A mesh that crossed itself before is judged on a selection by the region's crossings (its
  // faces against the mesh): a scan that crosses itself somewhere else (the devil mannequin does)
  // must not let the region's remeshing cross (its first isotropic remeshing of a 777-face region
  // took E 599 to 75,216 and every step after was refused). The whole mesh is not judged then:
  // the cow crosses itself at 137 faces, and its remeshings change which faces cross while the
  // flow rounds it.
  const bool crossedBefore = selfIntersects(mesh);
  const bool local = crossedBefore && !moving.selection().empty();
  const std::size_t crossingBefore = local ? selfIntersectingFaces(mesh, &region).size() : 0;
  std::vector<double> sigma = remeshTargets(moving, target, curvatureAdaptive, refineAt);
  PatchRemeshingOptions options;
  // Curvature-adaptive edges and a cage's long slivers need more vertices, but not without end.
  options.maxVertices = kMaxGrowth * mesh.vertexCount() + 1000;
  // A whole mesh with a border: the faces of its fixed rows (the border and its neighbours) lie
  // between the moving ones to the end of the face list, and a remeshing that must keep them at
  // their index collapsed nearly nothing (a coarse start came back with every vertex it had): they
  // keep their order instead (fair()'s contract). A selection keeps its faces' indices, and with
  // them remeshings that collapse little (its band of fixed faces lies between its moving ones
  // too): its runs were measured so, and it has no coarse start (docs/decisions.md, "Regions").
  options.regionMayShrink = moving.selection().empty();
  options.deadline = moving.deadline();
  // On its surface: the flowed surface has no sharp edges to keep (an angle of 180° finds none).
  std::unique_ptr<SurfaceProjector> surface;
  if (onSurface) {
    surface = std::make_unique<SurfaceProjector>(mesh, 180);
    options.surface = surface.get();
  }
  TriMesh remeshed;
  std::vector<std::uint8_t> remeshedRegion;
  for (int refinement = 0;; ++refinement) {
    if (!remeshWithinBudget(moving, region, sigma, maxMoving, options, remeshed, remeshedRegion)) return false;
    region.swap(remeshedRegion);  // remeshedRegion: the flags before
    if (remeshingFolds(moving, remeshed, region, remeshedRegion)) return false;
    if (local ? selfIntersectingFaces(remeshed, &region).size() > crossingBefore
              : !crossedBefore && selfIntersects(remeshed)) {
      // Two sheets of the surface closer than the target edge (a narrow tunnel, a thin wall): the
      // remesher's flips and moves put one through the other. Edges half as long within a few
      // target lengths of every crossing face, and again, resolve the gap where it is.
      if (local || refinement >= crossingRefinements) return false;
      halveTargetsNearCrossings(mesh, remeshed, kCrossingReach * target, sigma);
      region.swap(remeshedRegion);  // the flags before, for the next try
      continue;
    }
    break;
  }
  if (local && remeshingBlewUp(mesh, remeshedRegion, remeshed, region)) return false;
  return adopt(moving, std::move(remeshed), region);
}

}  // namespace elastica
