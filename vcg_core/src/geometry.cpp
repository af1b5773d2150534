#include <elastica/errors.h>
#include <elastica/geometry.h>
#include <elastica/parallel.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace elastica {
namespace {

// Scale-relative floors (in units of the mean edge length ℓ): below them a face or an edge is
// degenerate. Relative so that the result does not depend on the model's units.
constexpr double kRelativeLengthFloor = 1e-12;
constexpr double kRelativeAreaFloor = 1e-12;
// |cot| is clamped: a needle triangle must not dominate the Laplacian (angles under ~0.06°).
constexpr double kCotClamp = 1e3;

}  // namespace

double meanEdgeLength(const Topology& topo, const std::vector<Vec3>& p) {
  const int ne = topo.edgeCount();
  if (ne == 0) return 0;
  double sum = 0;
#pragma omp parallel for reduction(+ : sum) schedule(static) if (ne > kParallelGrain)
  for (int e = 0; e < ne; ++e) {
    const auto& ev = topo.edgeVertices(e);
    sum += (p[ev[1]] - p[ev[0]]).norm();
  }
  return sum / ne;
}

void computeGeometry(const Topology& topo, const std::vector<Vec3>& p, VertexArea areaType, Geometry& g) {
  const int nv = topo.vertexCount(), nf = topo.faceCount(), ne = topo.edgeCount();
  if (static_cast<int>(p.size()) != nv) {
    throw InvalidInputError("computeGeometry: " + std::to_string(p.size()) + " positions for a topology of " +
                            std::to_string(nv) + " vertices");
  }
  g.areaType = areaType;
  g.meanEdgeLength = meanEdgeLength(topo, p);
  if (!std::isfinite(g.meanEdgeLength)) throw NumericalError("computeGeometry: non-finite vertex position");
  const double ell = g.meanEdgeLength > 0 ? g.meanEdgeLength : 1.0;
  const double areaFloor = kRelativeAreaFloor * ell * ell;
  const double lengthFloor = kRelativeLengthFloor * ell;

  g.faceArea.resize(nf);
  g.faceNormal.resize(nf);
  g.cornerAngle.resize(3 * static_cast<size_t>(nf));
  g.cornerCot.resize(3 * static_cast<size_t>(nf));
  g.cornerArea.resize(3 * static_cast<size_t>(nf));
  g.edgeWeight.resize(ne);
  g.vertexArea.resize(nv);
  g.vertexNormal.resize(nv);
  g.angleSum.resize(nv);

  const auto& faces = topo.faces();
  std::size_t zeroAreaFaces = 0;
  double minArea = std::numeric_limits<double>::infinity();
#pragma omp parallel for reduction(+ : zeroAreaFaces) reduction(min : minArea) schedule(static) if (nf > kParallelGrain)
  for (int f = 0; f < nf; ++f) {
    const Face& t = faces[f];
    const Vec3 n = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
    const double twiceArea = n.norm();
    const double area = 0.5 * twiceArea;
    const bool degenerate = area <= areaFloor;
    g.faceArea[f] = area;
    g.faceNormal[f] = degenerate ? Vec3::Zero() : Vec3(n / twiceArea);
    if (degenerate) ++zeroAreaFaces; else minArea = std::min(minArea, area);

    double sqLen[3];  // squared length of the edge opposite corner k
    bool obtuse[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = p[t[(k + 1) % 3]] - p[t[k]];
      const Vec3 w = p[t[(k + 2) % 3]] - p[t[k]];
      const double d = u.dot(w);
      const size_t c = 3 * static_cast<size_t>(f) + k;
      // |u × w| is 2·area for every corner of the face; atan2 stays accurate near 0 and π.
      g.cornerAngle[c] = std::atan2(twiceArea, d);
      // A degenerate face has no meaningful cotangents: it gets zero weight rather than ±clamp,
      // which would make the Laplacian (and an explicit step) blow up around it.
      g.cornerCot[c] = degenerate ? 0.0 : std::clamp(d / std::max(twiceArea, areaFloor), -kCotClamp, kCotClamp);
      sqLen[(k + 1) % 3] = w.squaredNorm();  // edge t[k]–t[k+2] is opposite corner k+1
      obtuse[k] = d < 0;
    }
    for (int k = 0; k < 3; ++k) {
      const size_t c = 3 * static_cast<size_t>(f) + k;
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
        const size_t c1 = 3 * static_cast<size_t>(f) + (k + 1) % 3, c2 = 3 * static_cast<size_t>(f) + (k + 2) % 3;
        a = (sqLen[(k + 1) % 3] * g.cornerCot[c1] + sqLen[(k + 2) % 3] * g.cornerCot[c2]) / 8;
      }
      g.cornerArea[c] = a;
    }
  }
  g.minFaceArea = std::isfinite(minArea) ? minArea : 0.0;

  std::size_t zeroLengthEdges = 0;
#pragma omp parallel for reduction(+ : zeroLengthEdges) schedule(static) if (ne > kParallelGrain)
  for (int e = 0; e < ne; ++e) {
    const auto& ev = topo.edgeVertices(e);
    if ((p[ev[1]] - p[ev[0]]).norm() <= lengthFloor) ++zeroLengthEdges;
    const auto& oc = topo.edgeOppositeCorners(e);
    g.edgeWeight[e] = 0.5 * (g.cornerCot[oc[0]] + (oc[1] >= 0 ? g.cornerCot[oc[1]] : 0.0));
  }

  std::size_t zeroAreaVertices = 0, isolated = 0;
#pragma omp parallel for reduction(+ : zeroAreaVertices, isolated) schedule(static) if (nv > kParallelGrain)
  for (int v = 0; v < nv; ++v) {
    double area = 0, angles = 0;
    Vec3 normal = Vec3::Zero();
    for (int k = topo.cornerBegin(v); k < topo.cornerEnd(v); ++k) {
      const int c = topo.corner(k);
      area += g.cornerArea[c];
      angles += g.cornerAngle[c];
      normal += g.faceArea[c / 3] * g.faceNormal[c / 3];  // the paper's area-weighted normal
    }
    const double len = normal.norm();
    g.angleSum[v] = angles;
    if (topo.isIsolatedVertex(v)) {
      ++isolated;
      area = 0;
    } else if (area <= areaFloor || len <= areaFloor) {
      ++zeroAreaVertices;
      area = 0;
    }
    g.vertexArea[v] = area;
    g.vertexNormal[v] = area > 0 ? Vec3(normal / len) : Vec3::Zero();
  }

  g.degenerate.zeroAreaFaces = zeroAreaFaces;
  g.degenerate.zeroLengthEdges = zeroLengthEdges;
  g.degenerate.zeroAreaVertices = zeroAreaVertices;
  g.degenerate.isolatedVertices = isolated;
}

Geometry computeGeometry(const Topology& topo, const std::vector<Vec3>& p, VertexArea areaType) {
  Geometry g;
  computeGeometry(topo, p, areaType, g);
  return g;
}

}  // namespace elastica
