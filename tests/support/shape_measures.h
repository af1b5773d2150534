// Measures of a mesh's shape for the flow tests: roundness, torus aspect ratio, energy recomputed
// from scratch, and noisy test spheres.
#pragma once

#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/geometry.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>
#include <elastica/types.h>

#include <algorithm>
#include <cmath>

namespace elastica::test {

/// Distances of the vertices from their centroid.
struct RadiusStats {
  double mean = 0, min = 1e300, max = 0;
  double spread() const { return (max - min) / mean; }  ///< 0 for a round sphere
};

inline RadiusStats radii(const TriMesh& m) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : m.positions) c += p;
  c /= m.vertexCount();
  RadiusStats s;
  for (const Vec3& p : m.positions) {
    const double r = (p - c).norm();
    s.mean += r;
    s.min = std::min(s.min, r);
    s.max = std::max(s.max, r);
  }
  s.mean /= m.vertexCount();
  return s;
}

/// `m` with each vertex moved radially by a uniform factor in [1 − a, 1 + a].
inline TriMesh radialNoise(TriMesh m, double a, unsigned seed) {
  shapes::addRadialNoise(m, a, seed);
  return m;
}

/// The total curvature energy recomputed from scratch, independently of the flow's bookkeeping.
inline double energyOf(const TriMesh& m) {
  const Topology t(m.vertexCount(), m.faces);
  const Geometry g = computeGeometry(t, m.positions);
  return totalCurvatureEnergy(t, g, computeCurvature(t, g, m.positions));
}

/// R/r of a torus around z: half the sum and half the difference of the extreme distances from the axis.
inline double aspectRatio(const TriMesh& m) {
  double lo = 1e300, hi = 0;
  for (const Vec3& p : m.positions) {
    const double d = std::hypot(p.x(), p.y());
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return (hi + lo) / (hi - lo);
}

}  // namespace elastica::test
