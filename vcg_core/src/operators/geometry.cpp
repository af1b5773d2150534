// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/geometry.h>
#include "support/parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace elastica {
namespace {

// Scale-relative floors (in units of the mean edge length ℓ): below them a face or an edge is
// degenerate. Relative so that the result does not depend on the model's units.
constexpr double kRelativeLengthFloor = DegeneracyCounts::kRelativeLength;
constexpr double kRelativeAreaFloor = DegeneracyCounts::kRelativeArea;
// |cot| is clamped: a needle triangle must not dominate the Laplacian (angles under ~0.06°).
constexpr double kCotClamp = 1e3;

}  // namespace

double meanEdgeLength(const Topology& topo, const std::vector<Vec3>& p) {
  const int ne = topo.edgeCount();
  if (ne == 0) return 0;
  const double sum = parallelSum(ne, [&](int e) {
    const auto& ev = topo.edgeVertices(e);
    return (p[ev[1]] - p[ev[0]]).norm();
  });
  return sum / ne;
}

double boundingBoxDiagonal(const std::vector<Vec3>& p) {
  if (p.empty()) return 0;
  Vec3 lo = p.front(), hi = p.front();
  for (const Vec3& x : p) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  return (hi - lo).norm();
}

namespace {

// Σ of the angles arg(d_c + i·s_c) ∈ [0, π] of the corners [begin, end) of one vertex with one
// atan2: the product of the complex numbers d + i·s turns by the sum. The product is kept in the
// closed upper half-plane (negated, counting a half turn, whenever it leaves it), which is exact
// because each factor turns by at most π.
double angleSumOf(const Topology& topo, const Geometry& g, int begin, int end) {
  double re = 1, im = 0;
  int halfTurns = 0;
  for (int k = begin; k < end; ++k) {
    const int c = topo.corner(k);
    double d = g.cornerDot[c], s = 2 * g.faceArea[c / 3];
    const double scale = std::max(std::abs(d), s);
    if (!(scale > 0)) continue;  // coincident points: angle 0, as atan2(0, 0)
    d /= scale, s /= scale;      // |d + i·s| in [1, √2]: the product neither under- nor overflows
    const double r = re * d - im * s, i = re * s + im * d;
    if (i < 0) re = -r, im = -i, ++halfTurns;
    else re = r, im = i;
    if (std::abs(re) + im > 1e100) re *= 1e-100, im *= 1e-100;  // valence > 600 only
  }
  return halfTurns * M_PI + std::atan2(std::abs(im), re);
}

}  // namespace

double Geometry::cornerAngle(std::size_t c) const { return std::atan2(2 * faceArea[c / 3], cornerDot[c]); }

void computeGeometry(const Topology& topo, const std::vector<Vec3>& p, VertexArea areaType, Geometry& g,
                     const std::vector<std::uint8_t>* active, const GeometryKept& kept) {
  const int nv = topo.vertexCount(), nf = topo.faceCount(), ne = topo.edgeCount();
  if (static_cast<int>(p.size()) != nv) {
    throw InvalidInputError("computeGeometry: " + std::to_string(p.size()) + " positions for a topology of " +
                            std::to_string(nv) + " vertices");
  }
  if ((kept.faces && (static_cast<int>(kept.faces->size()) != nf || static_cast<int>(g.faceArea.size()) != nf)) ||
      (kept.edges && (static_cast<int>(kept.edges->size()) != ne || static_cast<int>(g.edgeLength.size()) != ne))) {
    throw InvalidInputError("computeGeometry: kept-value flags for another mesh");
  }
  if (active && static_cast<int>(active->size()) != nv) {
    throw InvalidInputError("computeGeometry: " + std::to_string(active->size()) + " vertex flags for a topology of " +
                            std::to_string(nv) + " vertices");
  }
  const std::vector<std::uint8_t>* keptFace = g.areaType == areaType ? kept.faces : nullptr;
  g.areaType = areaType;
  g.faceArea.resize(nf);
  g.faceNormal.resize(nf);
  g.cornerDot.resize(3 * static_cast<size_t>(nf));
  g.cornerCot.resize(3 * static_cast<size_t>(nf));
  g.cornerArea.resize(3 * static_cast<size_t>(nf));
  g.edgeLength.resize(ne);
  g.edgeWeight.resize(ne);
  g.vertexArea.resize(nv);
  g.ringArea.resize(nv);
  g.vertexNormal.resize(nv);
  g.angleSum.resize(nv);

  // Edge lengths first: their mean sets the scale of every floor below.
  const double lengthSum = parallelSum(ne, [&](int e) {
    const auto& ev = topo.edgeVertices(e);
    if (kept.edges && (*kept.edges)[e]) return g.edgeLength[e];
    return g.edgeLength[e] = (p[ev[1]] - p[ev[0]]).norm();
  });
  g.meanEdgeLength = ne > 0 ? lengthSum / ne : 0.0;
  if (!std::isfinite(g.meanEdgeLength)) throw NumericalError("computeGeometry: non-finite vertex position");
  const double ell = g.meanEdgeLength > 0 ? g.meanEdgeLength : 1.0;
  const double areaFloor = kRelativeAreaFloor * ell * ell;
  const double lengthFloor = kRelativeLengthFloor * ell;

  const auto& faces = topo.faces();
  struct FaceTally {
    std::size_t zeroArea = 0;
    double minArea = std::numeric_limits<double>::infinity();
  };
  const FaceTally faceTally = parallelReduce(nf, FaceTally{}, [&](int f, FaceTally& tally) {
    // A kept face: non-degenerate when computed (a unit normal) and now (its area above the floor).
    if (keptFace && (*keptFace)[f] && g.faceArea[f] > areaFloor && g.faceNormal[f] != Vec3::Zero()) {
      tally.minArea = std::min(tally.minArea, g.faceArea[f]);
      return;
    }
    const Face& t = faces[f];
    const Vec3 e[3] = {p[t[2]] - p[t[1]], p[t[0]] - p[t[2]], p[t[1]] - p[t[0]]};  // e[k] opposite corner k
    const Vec3 n = e[2].cross(-e[1]);
    const double twiceArea = n.norm();
    const double area = 0.5 * twiceArea;
    const bool degenerate = area <= areaFloor;
    g.faceArea[f] = area;
    g.faceNormal[f] = degenerate ? Vec3::Zero() : Vec3(n / twiceArea);
    if (degenerate) ++tally.zeroArea; else tally.minArea = std::min(tally.minArea, area);

    const double sqLen[3] = {e[0].squaredNorm(), e[1].squaredNorm(), e[2].squaredNorm()};
    const double inverse = degenerate ? 0.0 : 1.0 / std::max(twiceArea, areaFloor);
    const size_t c0 = 3 * static_cast<size_t>(f);
    bool obtuse[3];
    for (int k = 0; k < 3; ++k) {
      // u = P[k+1] − P[k] = e[k+2], w = P[k+2] − P[k] = −e[k+1]. |u × w| is 2·area at every corner.
      const double d = -e[(k + 2) % 3].dot(e[(k + 1) % 3]);
      g.cornerDot[c0 + k] = d;
      // A degenerate face has no meaningful cotangents: it gets zero weight rather than ±clamp,
      // which would make the Laplacian (and an explicit step) blow up around it.
      g.cornerCot[c0 + k] = std::clamp(d * inverse, -kCotClamp, kCotClamp);
      obtuse[k] = d < 0;
    }
    for (int k = 0; k < 3; ++k) {
      double a;
      if (degenerate) {
        a = 0;
      } else if (areaType == VertexArea::Barycentric) {
        a = area / 3;
      } else if (obtuse[0] || obtuse[1] || obtuse[2]) {
        // Meyer et al.: the Voronoi region leaves an obtuse triangle, use fixed fractions.
        a = obtuse[k] ? area / 2 : area / 4;
      } else {
        // Voronoi area of corner k: (|e_{k+1}|² cot θ_{k+1} + |e_{k+2}|² cot θ_{k+2}) / 8, where
        // e_j is the edge opposite corner j (both edges touch corner k).
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        a = (sqLen[k1] * g.cornerCot[c0 + k1] + sqLen[k2] * g.cornerCot[c0 + k2]) / 8;
      }
      g.cornerArea[c0 + k] = a;
    }
  }, [](FaceTally& t, const FaceTally& p) {
    t.zeroArea += p.zeroArea;
    t.minArea = std::min(t.minArea, p.minArea);
  });
  g.minFaceArea = std::isfinite(faceTally.minArea) ? faceTally.minArea : 0.0;

  const std::size_t zeroLengthEdges = parallelReduce(ne, std::size_t{0}, [&](int e, std::size_t& zero) {
    if (g.edgeLength[e] <= lengthFloor) ++zero;
    const auto& oc = topo.edgeOppositeCorners(e);
    g.edgeWeight[e] = 0.5 * (g.cornerCot[oc[0]] + (oc[1] >= 0 ? g.cornerCot[oc[1]] : 0.0));
  }, [](std::size_t& a, std::size_t b) { a += b; });

  struct VertexTally {
    std::size_t zeroArea = 0, isolated = 0;
  };
  const VertexTally vertexTally = parallelReduce(nv, VertexTally{}, [&](int v, VertexTally& tally) {
    if (active && !(*active)[v]) {
      g.angleSum[v] = g.ringArea[v] = g.vertexArea[v] = 0;
      g.vertexNormal[v] = Vec3::Zero();
      return;
    }
    double area = 0, ring = 0;
    Vec3 normal = Vec3::Zero();
    for (int k = topo.cornerBegin(v); k < topo.cornerEnd(v); ++k) {
      const int c = topo.corner(k);
      area += g.cornerArea[c];
      ring += g.faceArea[c / 3];
      normal += g.faceArea[c / 3] * g.faceNormal[c / 3];  // the paper's area-weighted normal
    }
    const double len = normal.norm();
    g.angleSum[v] = angleSumOf(topo, g, topo.cornerBegin(v), topo.cornerEnd(v));
    g.ringArea[v] = ring;
    if (topo.isIsolatedVertex(v)) {
      ++tally.isolated;
      area = 0;
    } else if (area <= areaFloor || len <= areaFloor) {
      ++tally.zeroArea;
      area = 0;
    }
    g.vertexArea[v] = area;
    g.vertexNormal[v] = area > 0 ? Vec3(normal / len) : Vec3::Zero();
  }, [](VertexTally& t, const VertexTally& p) {
    t.zeroArea += p.zeroArea;
    t.isolated += p.isolated;
  });

  g.degenerate.zeroAreaFaces = faceTally.zeroArea;
  g.degenerate.zeroLengthEdges = zeroLengthEdges;
  g.degenerate.zeroAreaVertices = vertexTally.zeroArea;
  g.degenerate.isolatedVertices = vertexTally.isolated;
}

Geometry computeGeometry(const Topology& topo, const std::vector<Vec3>& p, VertexArea areaType) {
  Geometry g;
  computeGeometry(topo, p, areaType, g);
  return g;
}

}  // namespace elastica
