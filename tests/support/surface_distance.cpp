#include "surface_distance.h"

#include <algorithm>
#include <array>
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

// Faces of a mesh binned in a uniform grid (by bounding box), for nearest-face queries: the exact
// nearest face, as brute force would find it, in time that grows with the patch, not with patch ×
// truth (a 2,000-edge hole's patch and truth hold ~10^5 faces each).
class FaceGrid {
 public:
  explicit FaceGrid(const TriMesh& m) : m_(m) {
    lo_ = hi_ = m.positions.empty() ? Vec3::Zero() : m.positions[0];
    for (const Vec3& p : m.positions) {
      lo_ = lo_.cwiseMin(p);
      hi_ = hi_.cwiseMax(p);
    }
    // About one face per cell on a surface: cells of ~2 mean edge lengths.
    double edge = 0;
    for (const Face& f : m.faces) edge += (m.positions[f[0]] - m.positions[f[1]]).norm();
    h_ = std::max(2 * edge / std::max<std::size_t>(m.faces.size(), 1), 1e-12 * (hi_ - lo_).norm() + 1e-300);
    h_ = std::max(h_, (hi_ - lo_).maxCoeff() / 500);  // at most ~500 cells a side
    for (int k = 0; k < 3; ++k) n_[k] = static_cast<int>((hi_[k] - lo_[k]) / h_) + 1;
    cells_.resize(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2]);
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      Vec3 a = m.positions[m.faces[f][0]], b = a;
      for (int v : m.faces[f]) {
        a = a.cwiseMin(m.positions[v]);
        b = b.cwiseMax(m.positions[v]);
      }
      const auto ca = cellOf(a), cb = cellOf(b);
      for (int x = ca[0]; x <= cb[0]; ++x)
        for (int y = ca[1]; y <= cb[1]; ++y)
          for (int z = ca[2]; z <= cb[2]; ++z) cells_[index(x, y, z)].push_back(static_cast<int>(f));
    }
  }

  // Squared distance from p to the nearest face: cube shells of cells around p's cell, until the
  // next shell cannot hold anything nearer.
  double nearest2(const Vec3& p) const {
    std::array<int, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = static_cast<int>(std::floor((p[k] - lo_[k]) / h_));
    int reach = 0;  // shells needed to cover the whole grid from c
    for (int k = 0; k < 3; ++k) reach = std::max({reach, std::abs(c[k]), std::abs(n_[k] - 1 - c[k])});
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r <= reach; ++r) {
      for (int x = std::max(c[0] - r, 0); x <= std::min(c[0] + r, n_[0] - 1); ++x)
        for (int y = std::max(c[1] - r, 0); y <= std::min(c[1] + r, n_[1] - 1); ++y)
          for (int z = std::max(c[2] - r, 0); z <= std::min(c[2] + r, n_[2] - 1); ++z) {
            if (std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])}) != r) continue;
            for (int f : cells_[index(x, y, z)]) {
              const Face& g = m_.faces[f];
              best = std::min(best, pointTriangleDistance2(p, m_.positions[g[0]], m_.positions[g[1]], m_.positions[g[2]]));
            }
          }
      const double clear = r * h_;  // anything in shell r + 1 or beyond is at least this far
      if (best <= clear * clear) break;
    }
    return best;
  }

 private:
  std::array<int, 3> cellOf(const Vec3& p) const {
    std::array<int, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = std::clamp(static_cast<int>((p[k] - lo_[k]) / h_), 0, n_[k] - 1);
    return c;
  }
  std::size_t index(int x, int y, int z) const { return (static_cast<std::size_t>(x) * n_[1] + y) * n_[2] + z; }

  const TriMesh& m_;
  Vec3 lo_, hi_;
  double h_ = 1;
  std::array<int, 3> n_{1, 1, 1};
  std::vector<std::vector<int>> cells_;
};

}  // namespace

DistanceStats sampledDistance(const TriMesh& a, const TriMesh& b, int perEdge) {
  if (b.faces.empty()) return {};
  const FaceGrid grid(b);
  double sum = 0, worst = 0;
  long count = 0;
  for (const Face& f : a.faces) {
    for (int i = 0; i <= perEdge; ++i) {
      for (int j = 0; i + j <= perEdge; ++j) {
        const double u = double(i) / perEdge, v = double(j) / perEdge;
        const Vec3 p = (1 - u - v) * a.positions[f[0]] + u * a.positions[f[1]] + v * a.positions[f[2]];
        const double best = grid.nearest2(p);
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
