#include <elastica/errors.h>
#include <elastica/shapes.h>
#include <elastica/subdivision.h>

#include <cmath>
#include <random>
#include <string>

namespace elastica::shapes {

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
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
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

void addRadialNoise(TriMesh& mesh, double amplitude, unsigned seed) {
  if (!(amplitude >= 0 && amplitude < 1)) throw InvalidInputError("addRadialNoise: need 0 <= amplitude < 1");
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  for (Vec3& p : mesh.positions) p *= 1 + u(rng);
}

}  // namespace elastica::shapes
