// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/energy_in_pieces.h"
#include "support/index_marks.h"
#include "support/parallel.h"

#include <elastica/energy.h>

#include <algorithm>
#include <cstdint>

namespace elastica {
namespace {

// The vertices in breadth-first order over the one-rings, each component from its smallest vertex:
// consecutive runs of it are compact pieces.
std::vector<int> breadthFirstOrder(const Topology& topo) {
  const int nv = topo.vertexCount();
  std::vector<int> order;
  order.reserve(nv);
  std::vector<std::uint8_t> seen(nv, 0);
  for (int start = 0; start < nv; ++start) {
    if (seen[start]) continue;
    seen[start] = 1;
    order.push_back(start);
    for (std::size_t head = order.size() - 1; head < order.size(); ++head) {  // `order` is the queue
      const int v = order[head];
      for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k)
        if (const int w = topo.ringVertex(k); !seen[w]) seen[w] = 1, order.push_back(w);
    }
  }
  return order;
}

}  // namespace

double activeEnergyInPieces(const Topology& topo, const std::vector<Vec3>& p, const std::vector<std::uint8_t>& active,
                            VertexArea area, const CurvatureOptions& opt, int pieceVertices) {
  const int nv = topo.vertexCount();
  const std::vector<Face>& faces = topo.faces();
  const double scale = meanEdgeLength(topo, p);  // the whole's floors (computeGeometry's mean edge)
  const std::vector<int> order = breadthFirstOrder(topo);
  std::vector<double> energy(nv, 0.0);
  std::vector<int> local(nv, -1), global, pieceFaceIds;
  std::vector<std::uint8_t> owned(nv, 0), flagged;
  IndexMarks faceMarks(faces.size()), vertexMarks(static_cast<std::size_t>(nv));
  std::vector<Face> pieceFaces;
  std::vector<Vec3> piecePositions, laplacianOfP;
  Topology pieceTopo;
  Geometry geo;
  Curvature c;
  for (int first = 0; first < nv; first += pieceVertices) {
    const int last = std::min(nv, first + pieceVertices);  // the piece owns order[first, last)
    // The faces at the piece's own vertices in the mesh's order, on their vertices numbered in
    // the mesh's order: each own vertex's fan listed as the whole Topology lists it.
    for (int i = first; i < last; ++i) {
      const int v = order[i];
      owned[v] = 1;
      for (int k = topo.cornerBegin(v); k < topo.cornerEnd(v); ++k) faceMarks.mark(topo.corner(k) / 3);
    }
    faceMarks.take(pieceFaceIds);
    for (int f : pieceFaceIds)
      for (int v : faces[f]) vertexMarks.mark(v);
    vertexMarks.take(global);
    for (std::size_t i = 0; i < global.size(); ++i) local[global[i]] = static_cast<int>(i);
    pieceFaces.resize(pieceFaceIds.size());
    for (std::size_t f = 0; f < pieceFaceIds.size(); ++f)
      for (int j = 0; j < 3; ++j) pieceFaces[f][j] = local[faces[pieceFaceIds[f]][j]];
    piecePositions.resize(global.size());
    flagged.assign(global.size(), 0);
    for (std::size_t i = 0; i < global.size(); ++i) {
      piecePositions[i] = p[global[i]];
      flagged[i] = owned[global[i]] && active[global[i]];
    }
    pieceTopo.rebuild(static_cast<int>(global.size()), pieceFaces);
    computeGeometry(pieceTopo, piecePositions, area, geo, &flagged, {}, scale);
    computeCurvature(pieceTopo, geo, piecePositions, opt, c, laplacianOfP, &flagged);
    for (std::size_t i = 0; i < global.size(); ++i)
      if (flagged[i]) energy[global[i]] = vertexCurvatureEnergy(pieceTopo, geo, c, static_cast<int>(i));
    for (int i = first; i < last; ++i) owned[order[i]] = 0;
  }
  // totalCurvatureEnergy's sum: the same chunks in the same order.
  return parallelSum(nv, [&](int v) { return active[v] ? energy[v] : 0.0; });
}

}  // namespace elastica
