#include "surface_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace elastica::bench {
namespace {

// Squared distance from p to triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
double pointTriangleDistance2(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).squaredNorm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).squaredNorm();
  const double denom = 1 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).squaredNorm();
}

}  // namespace

DistanceStats sampledDistance(const TriMesh& a, const TriMesh& b, int perEdge) {
  double sum = 0, worst = 0;
  long count = 0;
  for (const Face& f : a.faces) {
    for (int i = 0; i <= perEdge; ++i) {
      for (int j = 0; i + j <= perEdge; ++j) {
        const double u = double(i) / perEdge, v = double(j) / perEdge;
        const Vec3 p = (1 - u - v) * a.positions[f[0]] + u * a.positions[f[1]] + v * a.positions[f[2]];
        double best = std::numeric_limits<double>::infinity();
        for (const Face& g : b.faces)
          best = std::min(best, pointTriangleDistance2(p, b.positions[g[0]], b.positions[g[1]], b.positions[g[2]]));
        sum += best;
        worst = std::max(worst, best);
        ++count;
      }
    }
  }
  return {count ? std::sqrt(sum / count) : 0, std::sqrt(worst)};
}

TriMesh facesOf(const TriMesh& m, const std::vector<std::uint8_t>& keep) {
  TriMesh out;
  std::vector<int> index(m.positions.size(), -1);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (!keep[f]) continue;
    Face t;
    for (int k = 0; k < 3; ++k) {
      int& i = index[m.faces[f][k]];
      if (i < 0) {
        i = out.vertexCount();
        out.positions.push_back(m.positions[m.faces[f][k]]);
      }
      t[k] = i;
    }
    out.faces.push_back(t);
  }
  return out;
}

}  // namespace elastica::bench
