// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/subdivision.h>
#include <elastica/topology.h>
#include "mesh/edge_key.h"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>

namespace elastica {
namespace {

// The midpoint vertex of each edge, appended to the mesh on first use.
class Midpoints {
 public:
  explicit Midpoints(TriMesh& mesh) : mesh_(mesh) {}
  int operator()(int a, int b) {
    auto [it, inserted] = index_.try_emplace(edgeKey(a, b), mesh_.vertexCount());
    if (inserted) mesh_.positions.push_back(0.5 * (mesh_.positions[a] + mesh_.positions[b]));
    return it->second;
  }
  void reserve(size_t n) { index_.reserve(n); }
  // The midpoint vertex of edge a-b, or -1 if it was not made.
  int find(int a, int b) const {
    const auto it = index_.find(edgeKey(a, b));
    return it == index_.end() ? -1 : it->second;
  }

 private:
  TriMesh& mesh_;
  std::unordered_map<std::uint64_t, int> index_;
};

}  // namespace

void subdivideMidpoint(TriMesh& mesh, std::vector<std::uint8_t>* faceFlags) {
  Midpoints mid(mesh);
  mid.reserve(mesh.faces.size() * 2);
  std::vector<Face> next;
  next.reserve(4 * mesh.faces.size());
  std::vector<std::uint8_t> flags;
  if (faceFlags) flags.reserve(4 * faceFlags->size());
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const Face& t = mesh.faces[f];
    const int a = mid(t[0], t[1]), b = mid(t[1], t[2]), c = mid(t[2], t[0]);
    next.push_back({t[0], a, c});
    next.push_back({t[1], b, a});
    next.push_back({t[2], c, b});
    next.push_back({a, b, c});
    if (faceFlags) flags.insert(flags.end(), 4, (*faceFlags)[f]);
  }
  mesh.faces = std::move(next);
  if (faceFlags) *faceFlags = std::move(flags);
}

namespace {

// subdivideMidpointRegion's splits, the midpoints made in `mid`.
void splitRegion(TriMesh& mesh, std::vector<std::uint8_t>& faceFlags, Midpoints& mid) {
  // The edges to split: every edge of a flagged face.
  std::unordered_set<std::uint64_t> split;
  for (size_t f = 0; f < mesh.faces.size(); ++f)
    if (faceFlags[f])
      for (int k = 0; k < 3; ++k) split.insert(edgeKey(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]));
  mid.reserve(split.size());
  const size_t faceCount = mesh.faces.size();
  auto emit = [&](size_t parent, bool first, const Face& child) {
    if (first) {
      mesh.faces[parent] = child;
    } else {
      mesh.faces.push_back(child);
      faceFlags.push_back(faceFlags[parent]);
    }
  };
  const auto length2 = [&](int a, int b) { return (mesh.positions[a] - mesh.positions[b]).squaredNorm(); };
  for (size_t f = 0; f < faceCount; ++f) {
    const Face t = mesh.faces[f];
    int cut[3], cuts = 0;  // cut[k]: edge t[k]-t[k+1] is split
    for (int k = 0; k < 3; ++k) cuts += cut[k] = split.count(edgeKey(t[k], t[(k + 1) % 3])) != 0;
    if (cuts == 0) continue;
    if (cuts == 3) {  // flagged, or enclosed by the region: 1-to-4
      const int a = mid(t[0], t[1]), b = mid(t[1], t[2]), c = mid(t[2], t[0]);
      emit(f, true, {t[0], a, c});
      emit(f, false, {t[1], b, a});
      emit(f, false, {t[2], c, b});
      emit(f, false, {a, b, c});
    } else if (cuts == 1) {  // bisected from the opposite corner
      const int k = cut[0] ? 0 : cut[1] ? 1 : 2;
      const int p = t[k], q = t[(k + 1) % 3], r = t[(k + 2) % 3], m = mid(p, q);
      emit(f, true, {p, m, r});
      emit(f, false, {m, q, r});
    } else {  // two split edges, p-q and q-r around corner q: the corner triangle, then the quad
      const int k = !cut[0] ? 1 : !cut[1] ? 2 : 0;  // edge t[k]-t[k+1] is the first split one after the uncut
      const int p = t[k], q = t[(k + 1) % 3], r = t[(k + 2) % 3];
      const int m = mid(p, q), n = mid(q, r);
      emit(f, true, {m, q, n});
      if (length2(p, n) <= length2(m, r)) {
        emit(f, false, {p, m, n});
        emit(f, false, {p, n, r});
      } else {
        emit(f, false, {p, m, r});
        emit(f, false, {m, n, r});
      }
    }
  }
}

// Loop's vertex mask (Warren's β = 3/(8n), 3/16 at valence 3) at vertex v of `topo`, from positions p.
Vec3 loopVertex(const Topology& topo, const std::vector<Vec3>& p, int v) {
  const int n = topo.valence(v);
  if (n == 0) return p[v];
  const double beta = n == 3 ? 3.0 / 16 : 3.0 / (8.0 * n);
  Vec3 ring = Vec3::Zero();
  for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) ring += p[topo.ringVertex(k)];
  return (1 - n * beta) * p[v] + beta * ring;
}

// Loop's edge mask on interior edge e: 3/8 of its ends, 1/8 of the opposite corners.
Vec3 loopEdge(const Topology& topo, const std::vector<Vec3>& p, int e) {
  const auto& ev = topo.edgeVertices(e);
  const auto& oc = topo.edgeOppositeCorners(e);
  const std::vector<Face>& faces = topo.faces();
  const int c = faces[oc[0] / 3][oc[0] % 3], d = faces[oc[1] / 3][oc[1] % 3];
  return 0.375 * (p[ev[0]] + p[ev[1]]) + 0.125 * (p[c] + p[d]);
}

void requireFlags(const char* what, const TriMesh& mesh, const std::vector<std::uint8_t>& faceFlags) {
  if (faceFlags.size() != mesh.faces.size())
    throw InvalidInputError(std::string(what) + ": " + std::to_string(faceFlags.size()) + " flags for " +
                            std::to_string(mesh.faces.size()) + " faces");
}

}  // namespace

void subdivideMidpointRegion(TriMesh& mesh, std::vector<std::uint8_t>& faceFlags) {
  requireFlags("subdivideMidpointRegion", mesh, faceFlags);
  Midpoints mid(mesh);
  splitRegion(mesh, faceFlags, mid);
}

void subdivideLoopRegion(TriMesh& mesh, std::vector<std::uint8_t>& faceFlags) {
  requireFlags("subdivideLoopRegion", mesh, faceFlags);
  const int nv = mesh.vertexCount();
  const Topology topo(nv, mesh.faces);
  const std::vector<Vec3> p = mesh.positions;
  const std::vector<std::uint8_t> flagged = faceFlags;
  Midpoints mid(mesh);
  splitRegion(mesh, faceFlags, mid);
  // Loop's masks where their whole stencil lies in flagged faces: a vertex all of whose faces are
  // flagged (off the border), an edge whose two faces are.
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const auto& oc = topo.edgeOppositeCorners(e);
    if (oc[1] < 0 || !flagged[oc[0] / 3] || !flagged[oc[1] / 3]) continue;
    const auto& ev = topo.edgeVertices(e);
    mesh.positions[mid.find(ev[0], ev[1])] = loopEdge(topo, p, e);
  }
  for (int v = 0; v < nv; ++v) {
    bool inside = !topo.isBoundaryVertex(v) && !topo.isIsolatedVertex(v);
    for (int k = topo.cornerBegin(v); inside && k < topo.cornerEnd(v); ++k) inside = flagged[topo.corner(k) / 3] != 0;
    if (inside) mesh.positions[v] = loopVertex(topo, p, v);
  }
}

void subdivideLoop(TriMesh& mesh) {
  const int nv = mesh.vertexCount();
  const Topology topo(nv, mesh.faces);
  if (topo.boundaryEdgeCount() > 0)
    throw InvalidInputError("subdivideLoop: the mesh has " + std::to_string(topo.boundaryEdgeCount()) +
                            " border edges (Loop's masks here are for closed meshes)");
  const std::vector<Vec3>& p = mesh.positions;
  std::vector<Vec3> next(static_cast<std::size_t>(nv) + topo.edgeCount());
  for (int v = 0; v < nv; ++v) next[v] = loopVertex(topo, p, v);
  const std::vector<Face>& faces = topo.faces();
  for (int e = 0; e < topo.edgeCount(); ++e) next[nv + e] = loopEdge(topo, p, e);
  // The edge between a and b: from a's ring.
  auto edgeVertex = [&](int a, int b) {
    for (int k = topo.ringBegin(a); k < topo.ringEnd(a); ++k)
      if (topo.ringVertex(k) == b) return nv + topo.ringEdge(k);
    return -1;  // unreachable: every side of a face is an edge
  };
  std::vector<Face> children;
  children.reserve(4 * faces.size());
  for (const Face& t : faces) {
    const int a = edgeVertex(t[0], t[1]), b = edgeVertex(t[1], t[2]), c = edgeVertex(t[2], t[0]);
    children.push_back({t[0], a, c});
    children.push_back({t[1], b, a});
    children.push_back({t[2], c, b});
    children.push_back({a, b, c});
  }
  mesh.positions = std::move(next);
  mesh.faces = std::move(children);
}

}  // namespace elastica
