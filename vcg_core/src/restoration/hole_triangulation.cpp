#include "restoration/hole_triangulation.h"

#include <algorithm>
#include <limits>
#include <unordered_set>

namespace elastica {
namespace {

// Liepa's weight: the largest dihedral angle, measured as its cosine (the smaller, the worse),
// then the total area. Compared lexicographically.
struct Weight {
  double minCos = 1;   // cosine of the largest dihedral angle
  double area = 0;
  static Weight infinite() { return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}; }
  bool valid() const { return area < std::numeric_limits<double>::infinity(); }
  Weight operator+(const Weight& o) const { return {std::min(minCos, o.minCos), area + o.area}; }
  bool operator<(const Weight& o) const {
    // Cosines that differ by rounding only are a tie: then the smaller area wins.
    constexpr double kTie = 1e-12;
    if (minCos > o.minCos + kTie) return true;
    if (minCos < o.minCos - kTie) return false;
    return area < o.area;
  }
};

// Twice a triangle's area relative to its longest edge squared below which it counts as degenerate
// (its smallest angle is then below about 1e-10 degrees).
constexpr double kDegenerate = 1e-12;

Vec3 unitNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double len = n.norm();
  return len > 0 ? Vec3(n / len) : Vec3::Zero();
}

}  // namespace

std::optional<std::vector<Face>> triangulateHole(const std::vector<Vec3>& positions, const HoleLoop& loop,
                                                 const std::function<bool(int, int)>& edgeExists) {
  const int n = loop.edgeCount();
  if (loop.pinched || n < 3) return std::nullopt;
  const std::vector<int>& v = loop.vertices;
  auto P = [&](int i) -> const Vec3& { return positions[v[i]]; };

  // Existing mesh edges between loop vertices that are not loop edges: forbidden diagonals.
  std::unordered_set<long long> meshEdge;
  for (int i = 0; i < n; ++i) {
    for (int k = i + 2; k < n; ++k) {
      if (!(i == 0 && k == n - 1) && edgeExists(v[i], v[k])) meshEdge.insert(static_cast<long long>(i) * n + k);
    }
  }
  auto forbidden = [&](int i, int k) { return meshEdge.count(static_cast<long long>(i) * n + k) > 0; };

  // Normal of the mesh face on loop edge i → i+1: that face is (i+1, i, outside[i]).
  std::vector<Vec3> outsideNormal(n);
  for (int i = 0; i < n; ++i) outsideNormal[i] = unitNormal(P((i + 1) % n), P(i), positions[loop.outside[i]]);

  // W[i][k]: best triangulation of the sub-polygon i..k (k > i + 1); O[i][k]: its apex.
  std::vector<Weight> W(static_cast<size_t>(n) * n);
  std::vector<int> O(static_cast<size_t>(n) * n, -1);
  // Normal of the triangle on edge (i, k) inside the sub-polygon i..k: the mesh face for a loop
  // edge, else the apex triangle chosen for that sub-polygon.
  std::vector<Vec3> N(static_cast<size_t>(n) * n, Vec3::Zero());
  auto at = [n](int i, int k) { return static_cast<size_t>(i) * n + k; };
  for (int i = 0; i + 1 < n; ++i) N[at(i, i + 1)] = outsideNormal[i];

  for (int len = 2; len < n; ++len) {
    for (int i = 0; i + len < n; ++i) {
      const int k = i + len;
      Weight best = Weight::infinite();
      int bestM = -1;
      if (!forbidden(i, k)) {
        for (int m = i + 1; m < k; ++m) {
          const Weight& left = m - i > 1 ? W[at(i, m)] : Weight{};
          const Weight& right = k - m > 1 ? W[at(m, k)] : Weight{};
          if (!left.valid() || !right.valid()) continue;
          // A triangle without area (two copies of a vertex at one point, or three points on a
          // line) would be a sliver no later stage can repair: never use one.
          const double twiceArea = (P(m) - P(i)).cross(P(k) - P(i)).norm();
          const double longest = std::max({(P(m) - P(i)).squaredNorm(), (P(k) - P(m)).squaredNorm(), (P(i) - P(k)).squaredNorm()});
          if (!(twiceArea > kDegenerate * longest)) continue;
          const Vec3 nt = unitNormal(P(i), P(m), P(k));
          Weight w{std::min(nt.dot(N[at(i, m)]), nt.dot(N[at(m, k)])), 0.5 * twiceArea};
          // The whole polygon: its closing edge (0, n−1) borders a mesh face too.
          if (i == 0 && k == n - 1) w.minCos = std::min(w.minCos, nt.dot(outsideNormal[n - 1]));
          w = w + left + right;
          if (w < best) {
            best = w;
            bestM = m;
          }
        }
      }
      W[at(i, k)] = best;
      O[at(i, k)] = bestM;
      if (bestM >= 0) N[at(i, k)] = unitNormal(P(i), P(bestM), P(k));
    }
  }
  if (O[at(0, n - 1)] < 0) return std::nullopt;

  std::vector<Face> faces;
  faces.reserve(n - 2);
  std::vector<std::pair<int, int>> stack{{0, n - 1}};
  while (!stack.empty()) {
    const auto [i, k] = stack.back();
    stack.pop_back();
    const int m = O[at(i, k)];
    faces.push_back({v[i], v[m], v[k]});
    if (m - i > 1) stack.push_back({i, m});
    if (k - m > 1) stack.push_back({m, k});
  }
  return faces;
}

}  // namespace elastica
