// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/energy.h>
#include <elastica/mesh_curvature.h>
#include <elastica/sign_convention.h>
#include <elastica/topology.h>

#include "support/index_marks.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace elastica {

MeshCurvature measureCurvature(const TriMesh& mesh, const CurvatureMeasureOptions& opt) {
  return measureCurvature(Topology(mesh.vertexCount(), mesh.faces), mesh, opt);
}

MeshCurvature measureCurvature(const Topology& topo, const TriMesh& mesh, const CurvatureMeasureOptions& opt) {
  const Geometry geo = computeGeometry(topo, mesh.positions, opt.area);
  const Curvature c = computeCurvature(topo, geo, mesh.positions, opt.curvature);
  MeshCurvature out;
  out.energy = totalCurvatureEnergy(topo, geo, c);
  // Values leave the core here: the reported sign (+1/r on an outward sphere).
  out.H.resize(c.H.size());
  for (std::size_t i = 0; i < c.H.size(); ++i) out.H[i] = reportedMeanCurvature(c.H[i]);
  if (opt.curvature.h2k == H2KTreatment::PaperLambda) {
    out.Hlambda.resize(c.Hflow.size());
    for (std::size_t i = 0; i < c.Hflow.size(); ++i) out.Hlambda[i] = reportedMeanCurvature(c.Hflow[i]);
  }
  out.K = c.K;
  out.lambda = c.lambda;
  out.lambdaVertices = c.lambdaVertices;
  out.degenerate = geo.degenerate;
  out.eulerCharacteristic = topo.eulerCharacteristic();
  out.boundaryEdges = static_cast<std::size_t>(topo.boundaryEdgeCount());
  return out;
}

}  // namespace elastica

namespace elastica {

MeshCurvature measureCurvatureInPieces(const TriMesh& mesh, const CurvatureMeasureOptions& opt, int pieceVertices,
                                       MeshDefects* defects) {
  const int nv = mesh.vertexCount();
  if (opt.curvature.h2k == H2KTreatment::PaperLambda || nv <= pieceVertices) {
    const Topology whole(nv, mesh.faces);
    if (defects) *defects = {whole.inconsistentEdgeCount(), whole.nonManifoldVertexCount()};
    return measureCurvature(whole, mesh, opt);
  }
  if (defects) *defects = {};
  MeshCurvature out;
  out.H.assign(nv, 0.0);
  out.K.assign(nv, 0.0);
  std::vector<std::uint8_t> used(nv, 0);
  for (const Face& t : mesh.faces)
    for (int v : t) {
      if (v < 0 || v >= nv) return measureCurvature(mesh, opt);  // let it throw its message
      used[v] = 1;
    }
  long long edges = 0;
  std::vector<int> local(nv, -1);  // a piece's vertex number (set for the piece's vertices)
  IndexMarks inPiece(static_cast<std::size_t>(nv));  // a piece's vertices, read back sorted
  std::vector<int> global;
  TriMesh piece;
  std::vector<std::uint8_t> own;
  // One piece's topology and caches, their storage reused by the next: fresh ones per piece were
  // given back to the system and faulted in again.
  Topology topo;
  Geometry geo;
  Curvature c;
  std::vector<Vec3> laplacianOfP;
  for (int first = 0; first < nv; first += pieceVertices) {
    const int last = std::min(nv, first + pieceVertices);  // the piece's own vertices: [first, last)
    auto owned = [&](int v) { return v >= first && v < last; };
    // The faces at its own vertices, in the mesh's order, on their vertices numbered in the mesh's
    // order: each own vertex has its whole fan, listed as a whole-mesh Topology lists it.
    piece.faces.clear();
    // One scan of the mesh per piece: gathering every piece's faces in one pass was 3 % faster
    // on 2.6 M vertices, for 36 MB more at the peak.
    for (const Face& t : mesh.faces) {
      if (!owned(t[0]) && !owned(t[1]) && !owned(t[2])) continue;
      piece.faces.push_back(t);
      for (int v : t) inPiece.mark(v);
    }
    inPiece.take(global);
    for (std::size_t i = 0; i < global.size(); ++i) local[global[i]] = static_cast<int>(i);
    piece.positions.resize(global.size());
    for (std::size_t i = 0; i < global.size(); ++i) piece.positions[i] = mesh.positions[global[i]];
    for (Face& t : piece.faces)
      for (int& v : t) v = local[v];
    own.assign(global.size(), 0);
    for (std::size_t i = 0; i < global.size(); ++i) own[i] = owned(global[i]);

    topo.rebuild(piece.vertexCount(), piece.faces);
    if (defects) defects->nonManifoldVertices += topo.nonManifoldVertexCount(&own);
    // Only the own vertices' areas, normals and angle sums are read: the others are in the
    // piece for their positions (on the 2.6 M-vertex icosphere, 786,360 of the first piece's
    // 917,492 vertices; about 47,000 of 178,000 in the later ones).
    computeGeometry(topo, piece.positions, opt.area, geo, &own);
    computeCurvature(topo, geo, piece.positions, opt.curvature, c, laplacianOfP);
    out.energy += totalCurvatureEnergy(topo, geo, c, &own);
    for (std::size_t i = 0; i < global.size(); ++i) {
      if (!own[i]) continue;
      out.H[global[i]] = reportedMeanCurvature(c.H[i]);
      out.K[global[i]] = c.K[i];
      if (!geo.isRegular(static_cast<int>(i))) ++out.degenerate.zeroAreaVertices;
    }
    // Each edge once: in the piece of its smaller end; each face once: in the piece of its
    // smallest vertex. Degenerate as Geometry counts them (geometry.h), at the piece's mean edge.
    const double lengthFloor = DegeneracyCounts::kRelativeLength * geo.meanEdgeLength;
    for (int e = 0; e < topo.edgeCount(); ++e) {
      const auto& ev = topo.edgeVertices(e);
      if (!owned(std::min(global[ev[0]], global[ev[1]]))) continue;
      ++edges;
      out.boundaryEdges += topo.isBoundaryEdge(e);
      if (defects) defects->inconsistentEdges += topo.isInconsistentEdge(e);
      out.degenerate.zeroLengthEdges += geo.edgeLength[e] <= lengthFloor;
    }
    for (int f = 0; f < topo.faceCount(); ++f) {
      const Face& t = piece.faces[f];
      if (owned(std::min({global[t[0]], global[t[1]], global[t[2]]})))
        out.degenerate.zeroAreaFaces += geo.faceNormal[f].isZero(0);  // a degenerate face's normal
    }
  }
  for (int v = 0; v < nv; ++v) out.degenerate.isolatedVertices += !used[v];
  out.eulerCharacteristic = static_cast<int>(nv - edges + mesh.faceCount());
  return out;
}

}  // namespace elastica

namespace elastica {

namespace {

// Σ of the energy terms of the vertices marked in `marked` (indices past the mesh's end are
// ignored), each on its whole fan: the piece is every face at a marked vertex, on its vertices in
// the mesh's order.
double energyAt(const TriMesh& mesh, const std::vector<std::uint8_t>& marked, const CurvatureMeasureOptions& opt) {
  const int nv = mesh.vertexCount();
  std::vector<std::uint8_t> inPiece(nv, 0);
  TriMesh piece;
  for (const Face& t : mesh.faces) {
    bool at = false;
    for (int v : t) {
      if (v < 0 || v >= nv) return measureCurvature(mesh, opt).energy;  // let it throw its message
      at = at || marked[v];
    }
    if (!at) continue;
    piece.faces.push_back(t);
    for (int v : t) inPiece[v] = 1;
  }
  if (piece.faces.empty()) return 0;
  std::vector<int> local(nv, -1);
  std::vector<std::uint8_t> own;
  for (int v = 0; v < nv; ++v) {
    if (!inPiece[v]) continue;
    local[v] = piece.vertexCount();
    piece.positions.push_back(mesh.positions[v]);
    own.push_back(marked[v]);
  }
  for (Face& t : piece.faces)
    for (int& v : t) v = local[v];
  const Topology topo(piece.vertexCount(), piece.faces);
  Geometry geo;
  computeGeometry(topo, piece.positions, opt.area, geo, &own);
  const Curvature c = computeCurvature(topo, geo, piece.positions, opt.curvature);
  return totalCurvatureEnergy(topo, geo, c, &own);
}

// A face as a key that ignores where its vertex list starts (not its orientation).
std::array<int, 3> faceKey(const Face& t) {
  const int k = t[0] <= t[1] && t[0] <= t[2] ? 0 : (t[1] <= t[2] ? 1 : 2);
  return {t[k], t[(k + 1) % 3], t[(k + 2) % 3]};
}

}  // namespace

double curvatureEnergyChange(const TriMesh& before, const TriMesh& after, const CurvatureMeasureOptions& opt) {
  if (opt.curvature.h2k == H2KTreatment::PaperLambda) return measureCurvature(after, opt).energy - measureCurvature(before, opt).energy;
  const int nb = before.vertexCount(), na = after.vertexCount(), n = std::max(nb, na);
  // A vertex "moved" if it is not at the same index and position in both.
  std::vector<std::uint8_t> moved(n, 1);
  for (int v = 0; v < std::min(nb, na); ++v) moved[v] = !(before.positions[v] == after.positions[v]);
  auto kept = [&](const Face& t) {
    for (int v : t)
      if (v < 0 || v >= n || moved[v]) return false;
    return true;
  };
  // A face is the same in both if it is in both (first by index, then by value) with no vertex moved.
  const int fb = before.faceCount(), fa = after.faceCount();
  std::vector<std::uint8_t> sameB(fb, 0), sameA(fa, 0);
  for (int f = 0; f < std::min(fb, fa); ++f)
    sameB[f] = sameA[f] = before.faces[f] == after.faces[f] && kept(before.faces[f]);
  auto unmatchedKeys = [&](const TriMesh& m, const std::vector<std::uint8_t>& same) {
    std::vector<std::array<int, 3>> keys;
    for (int f = 0; f < m.faceCount(); ++f)
      if (!same[f] && kept(m.faces[f])) keys.push_back(faceKey(m.faces[f]));
    std::sort(keys.begin(), keys.end());
    return keys;
  };
  const std::vector<std::array<int, 3>> keysB = unmatchedKeys(before, sameB), keysA = unmatchedKeys(after, sameA);
  auto matchByValue = [&](const TriMesh& m, std::vector<std::uint8_t>& same, const std::vector<std::array<int, 3>>& other) {
    for (int f = 0; f < m.faceCount(); ++f)
      if (!same[f] && kept(m.faces[f])) same[f] = std::binary_search(other.begin(), other.end(), faceKey(m.faces[f]));
  };
  matchByValue(before, sameB, keysA);
  matchByValue(after, sameA, keysB);
  // The vertices whose fan differs: those of a face that is not the same, in either mesh.
  std::vector<std::uint8_t> marked(n, 0);
  auto markChanged = [&](const TriMesh& m, const std::vector<std::uint8_t>& same) {
    for (int f = 0; f < m.faceCount(); ++f)
      if (!same[f])
        for (int v : m.faces[f])
          if (v >= 0 && v < n) marked[v] = 1;
  };
  markChanged(before, sameB);
  markChanged(after, sameA);
  return energyAt(after, marked, opt) - energyAt(before, marked, opt);
}

}  // namespace elastica
