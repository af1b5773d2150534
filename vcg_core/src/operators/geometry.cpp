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

namespace {

// The inputs must belong to one mesh: positions, vertex flags and kept-value flags of its size.
void checkGeometryInputs(const Topology& topo, const std::vector<Vec3>& p, const Geometry& g,
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
}

void resizeGeometry(Geometry& g, int nv, int nf, int ne) {
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
}

// The mean edge length, computing the lengths not kept.
double edgeLengths(const Topology& topo, const std::vector<Vec3>& p, const GeometryKept& kept, Geometry& g) {
  const int ne = topo.edgeCount();
  const double lengthSum = parallelSum(ne, [&](int e) {
    const auto& ev = topo.edgeVertices(e);
    if (kept.edges && (*kept.edges)[e]) return g.edgeLength[e];
    return g.edgeLength[e] = (p[ev[1]] - p[ev[0]]).norm();
  });
  return ne > 0 ? lengthSum / ne : 0.0;
}

struct FaceTally {
  std::size_t zeroArea = 0;
  double minArea = std::numeric_limits<double>::infinity();
};

// The area of corner k of a face with edges of squared lengths sqLen (sqLen[j] opposite corner j),
// corner cotangents cot and corners obtuse.
double cornerAreaOf(int k, double area, bool degenerate, VertexArea areaType, const bool obtuse[3],
                    const double sqLen[3], const double* cot) {
  if (degenerate) return 0;
  if (areaType == VertexArea::Barycentric) return area / 3;
  // Meyer et al.: the Voronoi region leaves an obtuse triangle, use fixed fractions.
  if (obtuse[0] || obtuse[1] || obtuse[2]) return obtuse[k] ? area / 2 : area / 4;
  // Voronoi area of corner k: (|e_{k+1}|² cot θ_{k+1} + |e_{k+2}|² cot θ_{k+2}) / 8, where
  // e_j is the edge opposite corner j (both edges touch corner k).
  const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
  return (sqLen[k1] * cot[k1] + sqLen[k2] * cot[k2]) / 8;
}

// Face f's area, normal, corner dots, cotangents and corner areas (index-local: the face's own slots).
void faceGeometry(const Face& t, std::size_t f, const std::vector<Vec3>& p, VertexArea areaType, double areaFloor,
                  Geometry& g, FaceTally& tally) {
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
  const size_t c0 = 3 * f;
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
  for (int k = 0; k < 3; ++k)
    g.cornerArea[c0 + k] = cornerAreaOf(k, area, degenerate, areaType, obtuse, sqLen, &g.cornerCot[c0]);
}

// Every face's values; a kept face's are reused where they were and are non-degenerate.
FaceTally facesGeometry(const Topology& topo, const std::vector<Vec3>& p, VertexArea areaType, double areaFloor,
                        const std::vector<std::uint8_t>* keptFace, Geometry& g) {
  const auto& faces = topo.faces();
  return parallelReduce(topo.faceCount(), FaceTally{}, [&](int f, FaceTally& tally) {
    // A kept face: non-degenerate when computed (a unit normal) and now (its area above the floor).
    if (keptFace && (*keptFace)[f] && g.faceArea[f] > areaFloor && g.faceNormal[f] != Vec3::Zero()) {
      tally.minArea = std::min(tally.minArea, g.faceArea[f]);
      return;
    }
    faceGeometry(faces[f], static_cast<std::size_t>(f), p, areaType, areaFloor, g, tally);
  }, [](FaceTally& t, const FaceTally& p) {
    t.zeroArea += p.zeroArea;
    t.minArea = std::min(t.minArea, p.minArea);
  });
}

// The cotangent weights; returns the count of edges at or below the length floor.
std::size_t edgeWeights(const Topology& topo, double lengthFloor, Geometry& g) {
  return parallelReduce(topo.edgeCount(), std::size_t{0}, [&](int e, std::size_t& zero) {
    if (g.edgeLength[e] <= lengthFloor) ++zero;
    const auto& oc = topo.edgeOppositeCorners(e);
    g.edgeWeight[e] = 0.5 * (g.cornerCot[oc[0]] + (oc[1] >= 0 ? g.cornerCot[oc[1]] : 0.0));
  }, [](std::size_t& a, std::size_t b) { a += b; });
}

struct VertexTally {
  std::size_t zeroArea = 0, isolated = 0;
};

// Vertex v's area, ring area, normal and angle sum from its corners (index-local).
void vertexGeometry(const Topology& topo, int v, double areaFloor, Geometry& g, VertexTally& tally) {
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
}

// Every active vertex's values; an inactive vertex gets zeros.
VertexTally verticesGeometry(const Topology& topo, double areaFloor, const std::vector<std::uint8_t>* active,
                             Geometry& g) {
  return parallelReduce(topo.vertexCount(), VertexTally{}, [&](int v, VertexTally& tally) {
    if (active && !(*active)[v]) {
      g.angleSum[v] = g.ringArea[v] = g.vertexArea[v] = 0;
      g.vertexNormal[v] = Vec3::Zero();
      return;
    }
    vertexGeometry(topo, v, areaFloor, g, tally);
  }, [](VertexTally& t, const VertexTally& p) {
    t.zeroArea += p.zeroArea;
    t.isolated += p.isolated;
  });
}

}  // namespace

void computeGeometry(const Topology& topo, const std::vector<Vec3>& p, VertexArea areaType, Geometry& g,
                     const std::vector<std::uint8_t>* active, const GeometryKept& kept, double floorScale) {
  checkGeometryInputs(topo, p, g, active, kept);
  const std::vector<std::uint8_t>* keptFace = g.areaType == areaType ? kept.faces : nullptr;
  g.areaType = areaType;
  resizeGeometry(g, topo.vertexCount(), topo.faceCount(), topo.edgeCount());

  // Edge lengths first: their mean sets the scale of every floor below.
  g.meanEdgeLength = edgeLengths(topo, p, kept, g);
  if (floorScale > 0 && std::isfinite(g.meanEdgeLength)) g.meanEdgeLength = floorScale;
  if (!std::isfinite(g.meanEdgeLength)) throw NumericalError("computeGeometry: non-finite vertex position");
  const double ell = g.meanEdgeLength > 0 ? g.meanEdgeLength : 1.0;
  const double areaFloor = kRelativeAreaFloor * ell * ell;
  const double lengthFloor = kRelativeLengthFloor * ell;

  const FaceTally faceTally = facesGeometry(topo, p, areaType, areaFloor, keptFace, g);
  g.minFaceArea = std::isfinite(faceTally.minArea) ? faceTally.minArea : 0.0;
  const std::size_t zeroLengthEdges = edgeWeights(topo, lengthFloor, g);
  const VertexTally vertexTally = verticesGeometry(topo, areaFloor, active, g);

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
