// SPDX-License-Identifier: GPL-3.0-or-later
#include "flow/boundary_slide.h"

#include "mesh/surface_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace elastica {
namespace {

constexpr double kCornerDegrees = 30;

// The (up to two) neighbours of boundary vertex v along boundary edges.
std::array<int, 2> boundaryNeighbours(const Topology& topo, int v) {
  std::array<int, 2> nb{-1, -1};
  int n = 0;
  for (int k = topo.ringBegin(v); k < topo.ringEnd(v) && n < 2; ++k)
    if (topo.isBoundaryEdge(topo.ringEdge(k))) nb[n++] = topo.ringVertex(k);
  return nb;
}

}  // namespace

BoundarySlider::BoundarySlider(const Topology& topo, const std::vector<Vec3>& p) {
  std::vector<std::vector<int>> atVertex(topo.vertexCount());
  std::vector<std::array<int, 2>> ends;
  for (int e = 0; e < topo.edgeCount(); ++e) {
    if (!topo.isBoundaryEdge(e)) continue;
    const auto& ev = topo.edgeVertices(e);
    const int s = static_cast<int>(segment_.size());
    segment_.push_back({p[ev[0]], p[ev[1]]});
    ends.push_back(ev);
    atVertex[ev[0]].push_back(s);
    atVertex[ev[1]].push_back(s);
  }
  neighbourSegment_.resize(segment_.size());
  for (size_t s = 0; s < segment_.size(); ++s) {
    for (int k = 0; k < 2; ++k) {
      neighbourSegment_[s][k] = -1;
      for (int other : atVertex[ends[s][k]])
        if (other != static_cast<int>(s)) neighbourSegment_[s][k] = other;
    }
  }
  vertexSegment_.assign(topo.vertexCount(), -1);
}

void BoundarySlider::attach(const Topology& topo, const std::vector<Vec3>& p, const std::vector<std::uint8_t>& sliding) {
  vertexSegment_.assign(topo.vertexCount(), -1);
  for (int v = 0; v < topo.vertexCount(); ++v) {
    if (!sliding[v]) continue;
    // Corners of the boundary (a turn sharper than kCornerDegrees) stay where they are: sliding
    // would cut them.
    const auto nb = boundaryNeighbours(topo, v);
    if (nb[1] < 0) continue;
    const Vec3 in = (p[v] - p[nb[0]]).normalized(), out = (p[nb[1]] - p[v]).normalized();
    if (in.dot(out) < std::cos(kCornerDegrees * M_PI / 180)) continue;
    double best = std::numeric_limits<double>::infinity();
    for (size_t s = 0; s < segment_.size(); ++s) {
      const double d = (closestOnSegment(p[v], segment_[s][0], segment_[s][1]) - p[v]).squaredNorm();
      if (d < best) best = d, vertexSegment_[v] = static_cast<int>(s);
    }
  }
}

Vec3 BoundarySlider::project(int vertex, const Vec3& q) {
  // Search the vertex's segment and its neighbours along the polyline, a few segments each way:
  // a vertex slides by a fraction of an edge per step.
  constexpr int kReach = 3;
  int bestSeg = vertexSegment_[vertex];
  Vec3 best = closestOnSegment(q, segment_[bestSeg][0], segment_[bestSeg][1]);
  for (int dir = 0; dir < 2; ++dir) {
    int s = vertexSegment_[vertex], from = -1;
    for (int hop = 0; hop < kReach; ++hop) {
      // Walk away from where we came from.
      const auto& nb = neighbourSegment_[s];
      const int next = hop == 0 ? nb[dir] : (nb[0] == from ? nb[1] : nb[0]);
      if (next < 0) break;
      from = s;
      s = next;
      const Vec3 c = closestOnSegment(q, segment_[s][0], segment_[s][1]);
      if ((c - q).squaredNorm() < (best - q).squaredNorm()) best = c, bestSeg = s;
    }
  }
  vertexSegment_[vertex] = bestSeg;
  return best;
}

void BoundarySlider::slide(const Topology& topo, std::vector<Vec3>& p, const std::vector<std::uint8_t>& sliding,
                           double rate) {
  const int nv = topo.vertexCount();
  moved_.assign(p.begin(), p.end());
  for (int v = 0; v < nv; ++v) {
    if (!sliding[v] || vertexSegment_[v] < 0) continue;
    const auto nb = boundaryNeighbours(topo, v);
    if (nb[1] < 0) continue;
    const Vec3 chord = p[nb[1]] - p[nb[0]];
    const double len2 = chord.squaredNorm();
    if (len2 <= 0) continue;
    const Vec3 mid = 0.5 * (p[nb[0]] + p[nb[1]]);
    moved_[v] = p[v] + rate * ((mid - p[v]).dot(chord) / len2) * chord;
  }
  for (int v = 0; v < nv; ++v)
    if (sliding[v] && vertexSegment_[v] >= 0) p[v] = project(v, moved_[v]);
}

}  // namespace elastica
