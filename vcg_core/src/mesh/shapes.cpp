// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/errors.h>
#include <elastica/shapes.h>
#include <elastica/subdivision.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>

namespace elastica::shapes {
namespace {

// Quad (a, b, c, d), counter-clockwise seen from its front, as two triangles split along a–c or
// b–d. Callers alternate the diagonal so the triangulation has no preferred direction.
void addQuad(TriMesh& m, int a, int b, int c, int d, bool alongAC) {
  if (alongAC) {
    m.faces.push_back({a, b, c});
    m.faces.push_back({a, c, d});
  } else {
    m.faces.push_back({a, b, d});
    m.faces.push_back({b, c, d});
  }
}

}  // namespace

TriMesh icosphere(double radius, int level) {
  if (!(radius > 0) || level < 0 || level > 9)
    throw InvalidInputError("icosphere: need radius > 0 and 0 <= level <= 9");
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriMesh m;
  m.positions = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  m.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
             {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < level; ++l) subdivideMidpoint(m);
  for (Vec3& p : m.positions) p = radius * p.normalized();
  return m;
}

TriMesh torus(double R, double r, int nu, int nv) {
  if (!(r > 0) || !(R > r) || nu < 3 || nv < 3)
    throw InvalidInputError("torus: need R > r > 0 and at least 3 segments each way");
  TriMesh m;
  for (int i = 0; i < nu; ++i) {
    const double u = 2 * M_PI * i / nu;
    for (int j = 0; j < nv; ++j) {
      const double v = 2 * M_PI * j / nv;
      m.positions.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                               r * std::sin(v));
    }
  }
  auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      // (u, v) is a right-handed chart for the outward normal: ∂u × ∂v points outward.
      addQuad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), (i + j) % 2 == 0);
    }
  }
  return m;
}

TriMesh cylinder(double radius, double height, int around, int along) {
  if (!(radius > 0) || !(height > 0) || around < 3 || along < 1)
    throw InvalidInputError("cylinder: need radius, height > 0, at least 3 segments around and 1 along");
  TriMesh m;
  for (int j = 0; j <= along; ++j) {
    for (int i = 0; i < around; ++i) {
      const double u = 2 * M_PI * i / around;
      m.positions.emplace_back(radius * std::cos(u), radius * std::sin(u), height * j / along);
    }
  }
  auto id = [&](int i, int j) { return j * around + (i % around); };
  for (int j = 0; j < along; ++j) {
    for (int i = 0; i < around; ++i) {
      // ∂u × ∂z points outward.
      addQuad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), (i + j) % 2 == 0);
    }
  }
  return m;
}

TriMesh grid(int nx, int ny, double spacing) {
  if (nx < 1 || ny < 1 || !(spacing > 0)) throw InvalidInputError("grid: need nx, ny >= 1 and spacing > 0");
  TriMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.positions.emplace_back(i * spacing, j * spacing, 0.0);
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        m.faces.push_back({a, b, c});
        m.faces.push_back({a, c, d});
      } else {
        m.faces.push_back({a, b, d});
        m.faces.push_back({b, c, d});
      }
    }
  }
  return m;
}

TriMesh voxelSurface(const std::vector<std::array<int, 3>>& cells) {
  // Corners of each cube face, counter-clockwise seen from outside: +x, −x, +y, −y, +z, −z.
  static const int kCorner[6][4][3] = {{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}},
                                       {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}},
                                       {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},
                                       {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}},
                                       {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                                       {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}};
  static const int kNeighbour[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::set<std::array<int, 3>> occupied(cells.begin(), cells.end());
  std::map<std::array<int, 3>, int> index;
  TriMesh m;
  auto vertex = [&](const std::array<int, 3>& q) {
    auto [it, inserted] = index.try_emplace(q, m.vertexCount());
    if (inserted) m.positions.emplace_back(q[0], q[1], q[2]);
    return it->second;
  };
  for (const auto& c : occupied) {
    for (int d = 0; d < 6; ++d) {
      if (occupied.count({c[0] + kNeighbour[d][0], c[1] + kNeighbour[d][1], c[2] + kNeighbour[d][2]})) continue;
      int v[4];
      Vec3 centre = Vec3::Zero();
      for (int k = 0; k < 4; ++k) {
        v[k] = vertex({c[0] + kCorner[d][k][0], c[1] + kCorner[d][k][1], c[2] + kCorner[d][k][2]});
        centre += 0.25 * m.positions[v[k]];
      }
      // Four triangles around the square's centre: no valence-3 corners (spike tips for the
      // flow) and no diagonal that depends on orientation.
      m.positions.push_back(centre);
      const int ci = m.vertexCount() - 1;
      for (int k = 0; k < 4; ++k) m.faces.push_back({v[k], v[(k + 1) % 4], ci});
    }
  }
  return m;
}

TriMesh frameCage(int windowsX, int windowsY, int windowSize) {
  if (windowsX < 1 || windowsY < 1 || windowSize < 1) throw InvalidInputError("frameCage: need at least one window of size >= 1");
  const int period = windowSize + 1;
  std::vector<std::array<int, 3>> cells;
  for (int y = 0; y <= windowsY * period; ++y)
    for (int x = 0; x <= windowsX * period; ++x)
      if (x % period == 0 || y % period == 0) cells.push_back({x, y, 0});
  return voxelSurface(cells);
}

void addRadialNoise(TriMesh& mesh, double amplitude, unsigned seed) {
  if (!(amplitude >= 0 && amplitude < 1)) throw InvalidInputError("addRadialNoise: need 0 <= amplitude < 1");
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (Vec3& p : mesh.positions) p *= 1 + u(rng);
}

}  // namespace elastica::shapes
