// SPDX-License-Identifier: GPL-3.0-or-later
#include "restoration/hole_triangulation.h"

#include <algorithm>
#include <cmath>
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

// Liepa's dynamic programme over one polygon: `v` its vertices in loop order, `edgeNormal[i]` the
// normal of the mesh face on polygon edge i → i+1 (the last entry: the closing edge n−1 → 0), or
// zero where no face borders the edge (a chord that split a larger hole). O(n³) time, O(n²) memory.
std::optional<std::vector<Face>> liepa(const std::vector<Vec3>& positions, const std::vector<int>& v,
                                       const std::vector<Vec3>& edgeNormal, const std::function<bool(int, int)>& edgeExists) {
  const int n = static_cast<int>(v.size());
  auto P = [&](int i) -> const Vec3& { return positions[v[i]]; };
  // Existing mesh edges between polygon vertices that are not polygon edges: forbidden diagonals.
  std::unordered_set<long long> meshEdge;
  for (int i = 0; i < n; ++i) {
    for (int k = i + 2; k < n; ++k) {
      if (!(i == 0 && k == n - 1) && edgeExists(v[i], v[k])) meshEdge.insert(static_cast<long long>(i) * n + k);
    }
  }
  auto forbidden = [&](int i, int k) { return meshEdge.count(static_cast<long long>(i) * n + k) > 0; };
  // A polygon edge without a face beside it does not constrain the dihedral angle.
  auto dihedralCos = [](const Vec3& nt, const Vec3& beside) { return beside.isZero() ? 1.0 : nt.dot(beside); };

  // W[i][k]: best triangulation of the sub-polygon i..k (k > i + 1); O[i][k]: its apex.
  std::vector<Weight> W(static_cast<size_t>(n) * n);
  std::vector<int> O(static_cast<size_t>(n) * n, -1);
  // Normal of the triangle on edge (i, k) inside the sub-polygon i..k: the mesh face for a polygon
  // edge, else the apex triangle chosen for that sub-polygon.
  std::vector<Vec3> N(static_cast<size_t>(n) * n, Vec3::Zero());
  auto at = [n](int i, int k) { return static_cast<size_t>(i) * n + k; };
  for (int i = 0; i + 1 < n; ++i) N[at(i, i + 1)] = edgeNormal[i];

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
          Weight w{std::min(dihedralCos(nt, N[at(i, m)]), dihedralCos(nt, N[at(m, k)])), 0.5 * twiceArea};
          // The whole polygon: its closing edge (0, n−1) borders a mesh face too.
          if (i == 0 && k == n - 1) w.minCos = std::min(w.minCos, dihedralCos(nt, edgeNormal[n - 1]));
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

// One polygon of a hole to triangulate: its vertices in loop order, per edge the normal of the
// mesh face beside it (zero beside a chord) and the direction into the hole across that edge
// (zero beside a chord).
struct Polygon {
  std::vector<int> vertices;
  std::vector<Vec3> edgeNormal, edgeInward;
};

// Above this many edges a polygon is split by a chord before Liepa's O(n³) search: in one piece
// the search was 8 % of a 406-edge hole's fill (a profile), and it grows as n³ where the rest of
// the fill grows with the patch's area, n².
constexpr int kLiepaEdges = 100;

// The polygon seen along its area vector (Newell's normal): where it is one, a chord whose shadow
// crosses the border's, or whose midpoint's shadow lies outside it, leaves the hole (it would cut
// across a notch of a jagged border, or across the gap of a C-shaped hole).
class Shadow {
 public:
  Shadow(const std::vector<Vec3>& positions, const std::vector<int>& v)
      : positions_(positions), v_(v), normal_(polygonNormal(positions, v)) {
    if (normal_.isZero()) return;  // a tube's cut: no side to look from
    const Vec3 u = normal_.unitOrthogonal(), w = normal_.cross(u);
    for (int x : v) q_.emplace_back(positions[x].dot(u), positions[x].dot(w));
  }
  bool available() const { return !q_.empty(); }

  bool inside(int i, int j) const {
    const int n = static_cast<int>(q_.size());
    const Eigen::Vector2d a = q_[i], b = q_[j];
    auto side = [](const Eigen::Vector2d& p, const Eigen::Vector2d& r, const Eigen::Vector2d& s) {
      const double c = (r - p).x() * (s - p).y() - (r - p).y() * (s - p).x();
      return (c > 0) - (c < 0);
    };
    // A border vertex on the chord (a jagged border's corners line up) counts as a crossing: the
    // pieces would touch there.
    auto onChord = [&](const Eigen::Vector2d& p) {
      return side(a, b, p) == 0 && (p - a).dot(b - a) > 0 && (p - b).dot(a - b) > 0;
    };
    for (int k = 0; k < n; ++k) {
      const int l = (k + 1) % n;
      if (k != i && k != j && onChord(q_[k])) return false;
      if (k == i || k == j || l == i || l == j) continue;
      if (side(a, b, q_[k]) * side(a, b, q_[l]) < 0 && side(q_[k], q_[l], a) * side(q_[k], q_[l], b) < 0) return false;
    }
    const Vec3 mid = 0.5 * (positions_[v_[i]] + positions_[v_[j]]);
    return std::abs(windingNumber(positions_, v_, normal_, mid)) >= 0.5;
  }

 private:
  const std::vector<Vec3>& positions_;
  const std::vector<int>& v_;
  Vec3 normal_;
  std::vector<Eigen::Vector2d> q_;  // the vertices seen along normal_
};

// Triangulates `poly`: Liepa's search if it is small enough, else the polygon is cut in two along
// a chord and each side triangulated. The chord is the shortest one between two vertices that
// splits the polygon at least 1:2 (so the pieces shrink geometrically), leaves both ends into the
// hole (it lies on the hole's side of the mesh faces at both ends) and, seen along the polygon's
// area vector, stays inside it; chords are tried shortest first until both sides triangulate (a
// hole too curved for its shadow to be a polygon takes the shortest chords that leave into it).
// The dihedral angles across the chord are not weighed: the refinement and the fairing that
// follow move every vertex near it anyway.
// `failures` caps the chords that may fail over the whole recursion (each costs two sub-searches);
// once it is spent a large polygon is given up, and the caller falls back to one whole search.
std::optional<std::vector<Face>> triangulatePolygon(const std::vector<Vec3>& positions, const Polygon& poly,
                                                    const std::function<bool(int, int)>& edgeExists, int& failures) {
  const int n = static_cast<int>(poly.vertices.size());
  if (n <= kLiepaEdges) return liepa(positions, poly.vertices, poly.edgeNormal, edgeExists);
  auto P = [&](int i) -> const Vec3& { return positions[poly.vertices[i]]; };
  // Into the hole at vertex i: the mean of the inward directions across its two edges.
  auto inward = [&](int i) { return Vec3(poly.edgeInward[i] + poly.edgeInward[(i + n - 1) % n]); };
  std::vector<std::pair<double, std::pair<int, int>>> chords;
  for (int i = 0; i < n; ++i) {
    const Vec3 in = inward(i);
    for (int j = i + (n + 2) / 3; j <= i + 2 * n / 3 && j < n; ++j) {
      // Both pieces hold at least a third of the edges: j − i and n − (j − i) are in [n/3, 2n/3].
      const Vec3 d = P(j) - P(i);
      if ((!in.isZero() && d.dot(in) <= 0) || (!inward(j).isZero() && d.dot(inward(j)) >= 0)) continue;
      chords.push_back({d.squaredNorm(), {i, j}});
    }
  }
  std::sort(chords.begin(), chords.end());

  auto split = [&](int i, int j) -> std::optional<std::vector<Face>> {
    // Side one runs i → j and closes along the chord j → i; side two runs j → i (through n) and
    // closes along i → j. Both keep the loop's direction, so their faces keep its orientation.
    Polygon a, b;
    for (int k = i; k <= j; ++k) {
      a.vertices.push_back(poly.vertices[k]);
      const bool chord = k == j;
      a.edgeNormal.push_back(chord ? Vec3::Zero() : poly.edgeNormal[k]);
      a.edgeInward.push_back(chord ? Vec3::Zero() : poly.edgeInward[k]);
    }
    for (int k = j; k != i + n + 1; ++k) {
      const int kk = k % n;
      b.vertices.push_back(poly.vertices[kk]);
      const bool chord = kk == i;
      b.edgeNormal.push_back(chord ? Vec3::Zero() : poly.edgeNormal[kk]);
      b.edgeInward.push_back(chord ? Vec3::Zero() : poly.edgeInward[kk]);
    }
    auto left = triangulatePolygon(positions, a, edgeExists, failures);
    auto right = left ? triangulatePolygon(positions, b, edgeExists, failures) : std::nullopt;
    if (!right) {
      --failures;
      return std::nullopt;
    }
    left->insert(left->end(), right->begin(), right->end());
    return left;
  };
  // Each shadow test is O(n): at most this many, so that the search stays O(n²).
  constexpr int kShadowTests = 64;
  const Shadow shadow(positions, poly.vertices);
  for (bool useShadow : {true, false}) {
    if (useShadow && !shadow.available()) continue;
    int tests = 0;
    for (std::size_t t = 0; t < chords.size() && failures > 0; ++t) {
      const auto [i, j] = chords[t].second;
      if (edgeExists(poly.vertices[i], poly.vertices[j])) continue;
      if (useShadow) {
        if (++tests > kShadowTests) break;
        if (!shadow.inside(i, j)) continue;
      }
      if (auto faces = split(i, j)) return faces;
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<Face>> triangulateHole(const std::vector<Vec3>& positions, const HoleLoop& loop,
                                                 const std::function<bool(int, int)>& edgeExists) {
  const int n = loop.edgeCount();
  if (loop.pinched || n < 3) return std::nullopt;
  Polygon poly;
  poly.vertices = loop.vertices;
  for (int i = 0; i < n; ++i) {
    // The mesh face on loop edge i → i+1 is (i+1, i, outside[i]); the hole lies across the edge
    // from that face's third corner.
    const Vec3& a = positions[loop.vertices[i]];
    const Vec3& b = positions[loop.vertices[(i + 1) % n]];
    const Vec3& o = positions[loop.outside[i]];
    poly.edgeNormal.push_back(unitNormal(b, a, o));
    const Vec3 t = (b - a).normalized(), w = o - a;
    poly.edgeInward.push_back(-(w - w.dot(t) * t));
  }
  // A few failed chords are normal (a chord along an existing edge's pair of faces, a degenerate
  // triangle on one side); a hole where many fail is searched in one piece, as slow as that is.
  constexpr int kChordFailures = 16;
  int failures = kChordFailures;
  if (auto faces = triangulatePolygon(positions, poly, edgeExists, failures)) return faces;
  return n > kLiepaEdges ? liepa(positions, poly.vertices, poly.edgeNormal, edgeExists) : std::nullopt;
}

}  // namespace elastica
