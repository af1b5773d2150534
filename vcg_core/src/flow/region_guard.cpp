// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/region_guard.h"

#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/errors.h>
#include <elastica/geometry.h>
#include <elastica/topology.h>
#include "mesh/self_intersection.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace elastica {
namespace {

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

struct Defects {
  int nonManifoldVertices = 0, inconsistentEdges = 0;
};

// The connectivity defects the faces refuse in an input; throws on a non-manifold edge.
Defects defectsOf(const TriMesh& mesh) {
  const Topology topo(mesh.vertexCount(), mesh.faces);
  return {topo.nonManifoldVertexCount(), topo.inconsistentEdgeCount()};
}

// The region's faces and the faces around them (every face that uses one of their vertices), as
// a piece of their own: its energy over the region's vertices is theirs in the whole mesh (each
// has its whole fan in the piece), at the cost of the piece.
struct RegionPiece {
  TriMesh mesh;
  std::vector<std::uint8_t> regionVertex;  // per piece vertex: on a region face
  std::vector<std::uint8_t> near;          // per face of the whole mesh: in the piece
};

RegionPiece pieceAround(const TriMesh& mesh, const std::vector<std::uint8_t>& selection) {
  const int nv = mesh.vertexCount(), nf = mesh.faceCount();
  std::vector<std::uint8_t> inRegion(nv, 0);
  for (int f = 0; f < nf; ++f)
    if (selection.empty() || selection[f])
      for (int v : mesh.faces[f]) inRegion[v] = 1;
  RegionPiece p;
  p.near.assign(nf, 0);
  std::vector<int> local(nv, -1);
  for (int f = 0; f < nf; ++f) {
    const Face& face = mesh.faces[f];
    if (!(inRegion[face[0]] || inRegion[face[1]] || inRegion[face[2]])) continue;
    p.near[f] = 1;
    Face g;
    for (int k = 0; k < 3; ++k) {
      const int v = face[k];
      if (local[v] < 0) {
        local[v] = p.mesh.vertexCount();
        p.mesh.positions.push_back(mesh.positions[v]);
        p.regionVertex.push_back(inRegion[v]);
      }
      g[k] = local[v];
    }
    p.mesh.faces.push_back(g);
  }
  return p;
}

double energyOfPiece(const RegionPiece& p, const FlowOptions& opt) {
  const Topology topo(p.mesh.vertexCount(), p.mesh.faces);
  const Geometry geo = computeGeometry(topo, p.mesh.positions, opt.area);
  const Curvature c = computeCurvature(topo, geo, p.mesh.positions, opt.curvature);
  return totalCurvatureEnergy(topo, geo, c, &p.regionVertex);
}

}  // namespace

double regionEnergy(const TriMesh& mesh, const std::vector<std::uint8_t>& faces, const FlowOptions& opt) {
  return energyOfPiece(pieceAround(mesh, faces), opt);
}

RegionGuard::RegionGuard(const TriMesh& input, const std::vector<std::uint8_t>& selection, const FlowOptions& opt)
    : opt_(opt), splitsNeighbours_(opt.subdivisionLevels > 0) {
  opt_.progress = nullptr;  // the guard measures; it never reports progress
  before_ = measure(input, selection);
  outside_ = outsideFaces(input, selection, splitsNeighbours_);
  const Defects d = defectsOf(input);
  nonManifoldVertices_ = d.nonManifoldVertices;
  inconsistentEdges_ = d.inconsistentEdges;
}

RegionGuard::Measure RegionGuard::measure(const TriMesh& mesh, const std::vector<std::uint8_t>& selection) const {
  const RegionPiece p = pieceAround(mesh, selection);
  const TriMesh& piece = p.mesh;
  Measure m;
  m.energy = energyOfPiece(p, opt_);
  std::vector<std::array<std::uint64_t, 3>> points(piece.positions.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k) points[i][k] = bits(piece.positions[i][k] + 0.0);  // -0 is 0
  std::sort(points.begin(), points.end());
  for (std::size_t i = 1; i < points.size(); ++i) m.coincident += points[i] == points[i - 1];
  m.crossing = static_cast<int>(selfIntersectingFaces(mesh, &p.near).size());
  return m;
}

std::vector<RegionGuard::FaceKey> RegionGuard::outsideFaces(const TriMesh& mesh,
                                                            const std::vector<std::uint8_t>& selection,
                                                            bool splitsNeighbours) {
  std::vector<FaceKey> keys;
  if (selection.empty()) return keys;
  std::vector<std::uint8_t> inRegion;
  if (splitsNeighbours) {
    inRegion.assign(mesh.positions.size(), 0);
    for (int f = 0; f < mesh.faceCount(); ++f)
      if (selection[f])
        for (int v : mesh.faces[f]) inRegion[v] = 1;
  }
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (selection[f]) continue;
    if (splitsNeighbours) {  // a face with two corners on the region may share an edge with it
      const Face& t = mesh.faces[f];
      if (inRegion[t[0]] + inRegion[t[1]] + inRegion[t[2]] >= 2) continue;
    }
    std::array<std::array<std::uint64_t, 3>, 3> corner;
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) corner[k][d] = bits(mesh.positions[mesh.faces[f][k]][d]);
    const int first = static_cast<int>(std::min_element(corner.begin(), corner.end()) - corner.begin());
    FaceKey key;
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) key[3 * k + d] = corner[(first + k) % 3][d];
    keys.push_back(key);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::string RegionGuard::check(const TriMesh& output, const std::vector<std::uint8_t>& selection,
                               double& energyAfter) const {
  energyAfter = std::numeric_limits<double>::quiet_NaN();
  for (const Vec3& p : output.positions)
    if (!p.allFinite()) return "a vertex is not finite";
  try {
    const Defects d = defectsOf(output);
    if (d.nonManifoldVertices > nonManifoldVertices_) return "the output has a non-manifold vertex";
    if (d.inconsistentEdges > inconsistentEdges_) return "the output's faces are not consistently oriented";
  } catch (const InvalidInputError& e) {
    return std::string("the output is not a manifold mesh (") + e.what() + ")";
  }
  if (outsideFaces(output, selection, splitsNeighbours_) != outside_) return "a face off the region changed";
  const Measure after = measure(output, selection);
  energyAfter = after.energy;
  if (after.coincident > before_.coincident) return "two vertices of the region ended at one point";
  if (after.crossing > before_.crossing) return "faces of the region cross each other or the mesh";
  if (!(after.energy <= before_.energy)) return "the region's energy ended above its start";
  return {};
}

}  // namespace elastica
