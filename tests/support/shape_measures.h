// SPDX-License-Identifier: GPL-3.0-or-later
// Measures of a mesh's shape for the flow tests: roundness, torus aspect ratio, energy recomputed
// from scratch, and noisy test spheres.
#pragma once

#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/geometry.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>
#include <elastica/types.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace elastica::test {

/// Distances of the vertices from their centroid.
struct RadiusStats {
  double mean = 0, min = 1e300, max = 0;
  double spread() const { return (max - min) / mean; }  ///< 0 for a round sphere
};

/// Distances of the vertices from `centre`.
inline RadiusStats radiiAbout(const TriMesh& m, const Vec3& centre) {
  RadiusStats s;
  for (const Vec3& p : m.positions) {
    const double r = (p - centre).norm();
    s.mean += r;
    s.min = std::min(s.min, r);
    s.max = std::max(s.max, r);
  }
  s.mean /= m.vertexCount();
  return s;
}

inline RadiusStats radii(const TriMesh& m) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& p : m.positions) c += p;
  return radiiAbout(m, c / m.vertexCount());
}

/// The least-squares sphere through the vertices (algebraic fit: |p|² = 2 c·p + d, r² = d + |c|²).
struct Sphere {
  Vec3 centre = Vec3::Zero();
  double radius = 0;
};

inline Sphere fitSphere(const TriMesh& m) {
  Eigen::MatrixXd A(m.vertexCount(), 4);
  Eigen::VectorXd b(m.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) {
    const Vec3& p = m.positions[v];
    A.row(v) << 2 * p.x(), 2 * p.y(), 2 * p.z(), 1;
    b[v] = p.squaredNorm();
  }
  const Eigen::Vector4d x = A.colPivHouseholderQr().solve(b);
  Sphere s;
  s.centre = x.head<3>();
  s.radius = std::sqrt(x[3] + s.centre.squaredNorm());
  return s;
}

/// Distances of the vertices from the centre of their least-squares sphere: roundness that does
/// not depend on how evenly the vertices are spread over the surface.
inline RadiusStats fittedRadii(const TriMesh& m) { return radiiAbout(m, fitSphere(m).centre); }

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
