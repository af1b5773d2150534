// SPDX-License-Identifier: GPL-3.0-or-later
#include "restoration/patch_angles.h"

#include <elastica/vertex_faces.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace elastica {
namespace {

// A move or flip must raise the smallest angle it touches by more than this (degrees) to count:
// below it, passes would trade rounding errors.
constexpr double kGain = 1e-6;

// The cosine of a triangle's smallest angle (its largest corner cosine): comparisons need no
// inverse trigonometry, which took an eighth of a 200-edge fill's time.
double cosCorner(const Vec3& at, const Vec3& a, const Vec3& b) {
  const Vec3 u = a - at, v = b - at;
  const double n = u.norm() * v.norm();
  return n > 0 ? u.dot(v) / n : 1;
}

double degreesOfCos(double cosine) { return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / std::acos(-1.0); }

double smallestAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return degreesOfCos(std::max({cosCorner(a, b, c), cosCorner(b, c, a), cosCorner(c, a, b)}));
}

// A patch face is turned back over the mesh across a border edge when the cosine of the angle
// between the two faces' normals is below this (a dihedral angle above 120°).
constexpr double kTurnedCos = -0.5;

// Ears thinner than this are split (the 25° of issue 15).
constexpr double kEarDegrees = 25;

Vec3 faceNormal(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

class PatchAngles {
 public:
  PatchAngles(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
              double goodEnough, bool finishing)
      : m_(mesh), patch_(patchFace), sigma_(sigma), firstNew_(firstNew), goodEnough_(goodEnough), finishing_(finishing),
        faces_(faceListsOf(mesh)) {}

  // Each pass looks again only at what changed around since it last looked (the outcome of a move
  // or a flip depends on the positions of the vertices of its faces and of the faces across their
  // edges, and on those faces; the mesh outside the patch never changes): the same result as
  // looking at everything, at the cost of the changes. On the armadillo's 1,978-edge hole (170,000
  // patch vertices) the 8 passes over everything took an eighth of the fill's time in a profile.
  int movePass() {
    int moves = 0;
    grow();  // no pass adds vertices or faces: only the splits before and after the passes do
    for (int v = firstNew_; v < static_cast<int>(m_.positions.size()); ++v) {
      if (stamp_[v] <= vLooked_[v]) continue;
      vLooked_[v] = clock_;
      moves += place(v);
    }
    return moves;
  }

  // An ear: a patch face whose three corners are on the border (two border edges and the corner
  // between them), too thin because the two border edges differ in length. No flip or move can
  // widen it (its corners never move): its inner edge is split at the midpoint, and the new vertex
  // then becomes the apex of both border edges (movePass). On a 198-edge hole cut in CGAL's
  // armadillo every face below 25° was such an ear. So is an ear at a reflex corner, turned back
  // over the mesh whatever its angles (the bunny refined twice, a 792-edge hole: two border edges
  // of the ear lay flat on the mesh's faces, reversed); its new vertex is placed back across them.
  int splitEars() {
    return splitEachPatchFace([&](int f, const Face& t) {
      if (t[0] >= firstNew_ || t[1] >= firstNew_ || t[2] >= firstNew_) return false;
      if (faceAngle(t) >= kEarDegrees && !turnedOverMesh(f)) return false;
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        const int g = across(f, a, b);
        if (g < 0 || !patch_[g]) continue;  // a border edge
        split(f, g, a, b);
        return true;
      }
      return false;
    });
  }

  // Finishing only: where a face on a border edge stays below 25°, one of its apex's two edges in
  // it is split at the midpoint and the new vertex and the apex are placed again; kept only if
  // the smallest angle around them rises. One apex cannot serve two border edges of unequal length
  // at a reflex corner well (the armadillo's 1,978-edge hole: edges of 0.058 and 0.217 left 23.9°),
  // nor several border edges at once: the split gives the far edge its own apex, with a face
  // between the two at the corner.
  int splitBorderApexes() {
    return splitEachPatchFace([&](int f, const Face& t) {
      if (faceAngle(t) >= kEarDegrees) return false;
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3], v = t[(k + 2) % 3];
        if (v < firstNew_ || !onBorder(f, a, b)) continue;
        // v's two edges in f, directed as in f: (b, v) and (v, a).
        for (auto [p, q] : {std::pair{b, v}, std::pair{v, a}}) {
          const int g = across(f, p, q);
          if (g >= 0 && patch_[g] && trySplit(f, g, p, q, v)) return true;
        }
        return false;  // with an apex inside the patch, f has one border edge at most
      }
      return false;
    });
  }

  int flipPass() {
    int flips = 0;
    grow();
    for (int f = 0; f < static_cast<int>(m_.faces.size()); ++f) {
      if (!patch_[f]) continue;
      const Face& t = m_.faces[f];
      if (std::max({stamp_[t[0]], stamp_[t[1]], stamp_[t[2]]}) <= fLooked_[f]) continue;
      fLooked_[f] = clock_;
      for (int k = 0; k < 3; ++k) {
        const int a = m_.faces[f][k], b = m_.faces[f][(k + 1) % 3];
        const int g = across(f, a, b);
        if (g > f && patch_[g] && flip(f, g, a, b)) {
          ++flips;
          break;  // face f changed: its edges are new
        }
      }
    }
    return flips;
  }

 private:
  // Calls `trySplitAt(f, t)` (true: it split) on each patch face f, as t, that was there when the
  // pass began: the faces a split appends are new and wait for the next pass. Returns the splits.
  template <class TrySplit>
  int splitEachPatchFace(TrySplit trySplitAt) {
    int splits = 0;
    const int faceCount = static_cast<int>(m_.faces.size());
    for (int f = 0; f < faceCount; ++f) {
      if (!patch_[f]) continue;
      const Face t = m_.faces[f];  // a copy: the split rewrites face f
      splits += trySplitAt(f, t);
    }
    return splits;
  }

  // The smallest angle (degrees) of face t where it is.
  double faceAngle(const Face& t) const { return smallestAngle(m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]); }

  // The face other than f on edge (a, b), or -1.
  int across(int f, int a, int b) const {
    for (int g : faces_[a]) {
      if (g == f) continue;
      const Face& t = m_.faces[g];
      if (t[0] == b || t[1] == b || t[2] == b) return g;
    }
    return -1;
  }

  // Whether (a, b), an edge of patch face f, is a border edge (no patch face on its other side).
  bool onBorder(int f, int a, int b) const {
    const int g = across(f, a, b);
    return g < 0 || !patch_[g];
  }

  // The smallest angle (degrees) of v's faces where they are.
  double worstHere(int v) const {
    double worst = 180;
    for (int f : faces_[v]) {
      const Face& t = m_.faces[f];
      worst = std::min(worst, faceAngle(t));
    }
    return worst;
  }

  // Splits edge (p, q) (directed as in face f; g is across it; v one of its ends, inside the
  // patch), places the new vertex and v, and keeps the split if the smallest angle around them
  // rose; otherwise puts everything back.
  bool trySplit(int f, int g, int p, int q, int v) {
    const double before = worstHere(v);
    const Vec3 oldV = m_.positions[v];
    const Face oldF = m_.faces[f], oldG = m_.faces[g];
    split(f, g, p, q);
    const int m = static_cast<int>(m_.positions.size()) - 1;
    for (int round = 0; round < 2; ++round) {
      place(m);
      place(v);
    }
    if (std::min(worstHere(m), worstHere(v)) > before + kGain) return true;
    unsplit(f, g, oldF, oldG);
    m_.positions[v] = oldV;
    touch(v);
    return false;
  }

  // Moves v to the best of its candidate places; true if it moved.
  bool place(int v) {
    Vec3 normal, centroid;
    int neighbours = 0;
    if (!ringOf(v, normal, centroid, neighbours)) return false;
    const Vec3 here = m_.positions[v];
    double best = worstAngle(v, here, normal);
    if (best >= goodEnough_) return false;
    centroid /= neighbours;
    std::vector<Vec3> candidates{centroid};
    std::vector<std::pair<int, int>> borderEdges;  // the border edges v faces (v is their apex)
    addApexCandidates(v, here, candidates, borderEdges);
    const double reach = meanEdge(v, here, neighbours);
    const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
    addSmallSteps(here, reach, e1, e2, candidates);
    Vec3 bestPlace = here;
    for (const Vec3& c : candidates) {
      const Vec3 p = here + (c - here) - (c - here).dot(normal) * normal;  // within the tangent plane
      const double a = worstAngle(v, p, normal);
      if (a > best + kGain) {
        best = a;
        bestPlace = p;
      }
    }
    if (finishing_ && !borderEdges.empty()) {
      const auto [c1, c2] = searchPlane(borderEdges, normal, e1, e2);
      compassSearch(v, normal, reach, c1, c2, best, bestPlace);
    }
    if (bestPlace == here) return false;
    m_.positions[v] = bestPlace;
    touch(v);
    return true;
  }

  // v's faces, all in the patch (false otherwise, or with no faces or no normal: v stays): their
  // summed normal, unit, and the sum of v's neighbours over them (`neighbours` of them, each once
  // a face).
  bool ringOf(int v, Vec3& normal, Vec3& centroid, int& neighbours) const {
    const std::vector<int>& around = faces_[v];
    if (around.empty()) return false;
    normal = Vec3::Zero(), centroid = Vec3::Zero();
    for (int f : around) {
      if (!patch_[f]) return false;  // only vertices inside the patch move
      const Face& t = m_.faces[f];
      normal += faceNormal(m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]);
      for (int x : t)
        if (x != v) {
          centroid += m_.positions[x];
          ++neighbours;
        }
    }
    if (!(normal.norm() > 0)) return false;
    normal.normalize();
    return true;
  }

  // For each border edge v faces (into `borderEdges`), into `candidates`: the apex of the
  // equilateral triangle on it on v's side, halfway there, the apex across it, and v mirrored.
  void addApexCandidates(int v, const Vec3& here, std::vector<Vec3>& candidates,
                         std::vector<std::pair<int, int>>& borderEdges) const {
    for (int f : faces_[v]) {
      const Face& t = m_.faces[f];
      int k = 0;
      while (t[k] != v) ++k;
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const int g = across(f, a, b);
      if (g >= 0 && patch_[g]) continue;
      borderEdges.push_back({a, b});
      const Vec3 mid = 0.5 * (m_.positions[a] + m_.positions[b]), ab = m_.positions[b] - m_.positions[a];
      Vec3 side = (here - mid) - (here - mid).dot(ab) / ab.squaredNorm() * ab;
      if (!(side.norm() > 0)) continue;
      candidates.push_back(mid + std::sqrt(3.0) / 2 * ab.norm() * side.normalized());
      candidates.push_back(0.5 * (candidates.back() + here));  // halfway, in case the full move folds
      // And across the edge: where v lies on the mesh's side of it (a split ear's midpoint at a
      // reflex corner), the way back is there.
      candidates.push_back(mid - std::sqrt(3.0) / 2 * ab.norm() * side.normalized());
      candidates.push_back(here - 2 * side);  // v mirrored in the edge
    }
  }

  // The mean length of v's edges (each counted once a face, as ringOf counts the neighbours).
  double meanEdge(int v, const Vec3& here, int neighbours) const {
    double reach = 0;
    for (int f : faces_[v])
      for (int x : m_.faces[f])
        if (x != v) reach += (m_.positions[x] - here).norm();
    return reach / neighbours;
  }

  // Small steps around v: where the ideal places fold a face or trade one thin face for another,
  // a step of a tenth or a quarter of the mean edge often helps.
  static void addSmallSteps(const Vec3& here, double reach, const Vec3& e1, const Vec3& e2,
                            std::vector<Vec3>& candidates) {
    for (double step : {0.1, 0.25})
      for (int k = 0; k < 8; ++k) {
        const double phi = k * std::acos(-1.0) / 4;
        candidates.push_back(here + step * reach * (std::cos(phi) * e1 + std::sin(phi) * e2));
      }
  }

  // The plane compassSearch steps in, as two unit directions: v's tangent plane (e1, e2), but for
  // an apex of two border edges that meet at a corner, the plane of those two edges (where
  // cornerBound, hole_boundary.h, finds the corner's best split): on the armadillo's 794-edge hole
  // (a 39.2° corner between border edges of 0.10 and 0.39) the tangent-plane search stopped at
  // 18.248°, under the bound's 18.260°; this one reaches 18.95° (both faces at the corner
  // balanced). Its two faces lie across that corner, nearly in its plane, so the steps stay as small.
  std::pair<Vec3, Vec3> searchPlane(const std::vector<std::pair<int, int>>& borderEdges, const Vec3& normal,
                                    const Vec3& e1, const Vec3& e2) const {
    if (borderEdges.size() != 2) return {e1, e2};
    const auto [a0, b0] = borderEdges[0];
    const auto [a1, b1] = borderEdges[1];
    const int c = b0 == a1 ? b0 : b1 == a0 ? b1 : -1;
    if (c < 0) return {e1, e2};
    const int x = c == b0 ? a0 : b0, y = c == b0 ? b1 : a1;
    Vec3 n = (m_.positions[x] - m_.positions[c]).cross(m_.positions[y] - m_.positions[c]);
    if (!(n.norm() > 0)) return {e1, e2};
    n.normalize();
    if (n.dot(normal) < 0) n = -n;
    const Vec3 c1 = n.unitOrthogonal();
    return {c1, n.cross(c1)};
  }

  // In a finishing pass and for the apex of a border edge only, a compass search from `bestPlace`
  // (16 directions in the plane of c1 and c2, the step halved down to a two-thousandth of the mean
  // edge), raising `best`: an apex shared by two border edges of unequal length has one best place
  // between them (cornerBound, hole_boundary.h), on a ridge of the smallest angle that the fixed
  // steps missed by 0.5–1° (a 39° corner between border edges of 0.10 and 0.39: 17.5° instead of
  // its 18.26°). Not before the flow, which moves the apexes again (and the flow stopped at a
  // settled shape then ended 3·10⁻⁴ of the radius away from the plateau's on a cylinder hole), and
  // not inside the patch: a tangential move leaves the surface by its square times the curvature.
  void compassSearch(int v, const Vec3& normal, double reach, const Vec3& c1, const Vec3& c2, double& best,
                     Vec3& bestPlace) const {
    constexpr int kMaxProbes = 64;  // bounds a slow creep (each move gains at least kGain)
    int probes = 0;
    for (double step = 0.05 * reach; step > 0.0005 * reach && probes < kMaxProbes; ++probes) {
      bool moved = false;
      for (int k = 0; k < 16 && !moved; ++k) {
        const double phi = k * std::acos(-1.0) / 8;
        const Vec3 p = bestPlace + step * (std::cos(phi) * c1 + std::sin(phi) * c2);
        const double a = worstAngle(v, p, normal);
        if (a > best + kGain) {
          best = a;
          bestPlace = p;
          moved = true;
        }
      }
      if (!moved) step *= 0.5;
    }
  }

  // The smallest angle (degrees) of v's faces with v at p; -1 if one would turn against `normal`.
  double worstAngle(int v, const Vec3& p, const Vec3& normal) const {
    double largestCos = -1;
    for (int f : faces_[v]) {
      std::array<Vec3, 3> q;
      for (int k = 0; k < 3; ++k) q[k] = m_.faces[f][k] == v ? p : m_.positions[m_.faces[f][k]];
      const Vec3 n = faceNormal(q[0], q[1], q[2]);
      if (n.dot(normal) <= 0) return -1;
      // The edge opposite v, if on the border: the face must not lie back over the mesh's face.
      int k = 0;
      while (m_.faces[f][k] != v) ++k;
      if (turnedOverMesh(n, f, m_.faces[f][(k + 1) % 3], m_.faces[f][(k + 2) % 3])) return -1;
      largestCos = std::max({largestCos, cosCorner(q[0], q[1], q[2]), cosCorner(q[1], q[2], q[0]), cosCorner(q[2], q[0], q[1])});
    }
    return degreesOfCos(largestCos);
  }

  // Whether a patch face with normal n, on the border edge (x, y) whose other face is found by
  // skipping face `skip`, lies turned back over the mesh's face there (their normals more than
  // kTurnedCos apart: a dihedral angle above 120°).
  bool turnedOverMesh(const Vec3& n, int skip, int x, int y) const {
    if (x >= firstNew_ || y >= firstNew_) return false;
    const int h = across(skip, x, y);
    if (h < 0 || patch_[h]) return false;
    const Face& t = m_.faces[h];
    const Vec3 nh = faceNormal(m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]);
    return n.dot(nh) < kTurnedCos * n.norm() * nh.norm();
  }

  // Whether patch face f lies turned back over the mesh across one of its border edges.
  bool turnedOverMesh(int f) const {
    const Face& t = m_.faces[f];
    const Vec3 n = faceNormal(m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]);
    for (int k = 0; k < 3; ++k)
      if (turnedOverMesh(n, f, t[k], t[(k + 1) % 3])) return true;
    return false;
  }

  // Flips edge (a, b) between f = (a, b, c) and g = (b, a, d) into (a, d, c), (b, c, d) if that
  // raises the smaller angle of the two faces and nothing turns over. A face turned back over the
  // mesh across a border edge counts as worse than any angle: on the armadillo's 1,978-edge hole
  // a patch face on a 50.7° border corner lay on the wrong side of its border edge (its apex served
  // four border edges), the flow cannot move a face back through flat, and the flip to the
  // corner's ear undoes it.
  bool flip(int f, int g, int a, int b) {
    const int c = third(f, a, b), d = third(g, b, a);
    if (c == d || across(-1, c, d) >= 0) return false;  // the new edge exists already
    const Vec3 &pa = m_.positions[a], &pb = m_.positions[b], &pc = m_.positions[c], &pd = m_.positions[d];
    const Vec3 nf = faceNormal(pa, pb, pc), ng = faceNormal(pb, pa, pd);
    const Vec3 n1 = faceNormal(pa, pd, pc), n2 = faceNormal(pb, pc, pd);
    const bool turnedBefore = turnedOverMesh(nf, f, b, c) || turnedOverMesh(nf, f, c, a) ||
                              turnedOverMesh(ng, g, a, d) || turnedOverMesh(ng, g, d, b);
    const bool turnedAfter = turnedOverMesh(n1, g, a, d) || turnedOverMesh(n1, f, c, a) ||
                             turnedOverMesh(n2, f, b, c) || turnedOverMesh(n2, g, d, b);
    if (turnedAfter) return false;
    const double before = turnedBefore ? -1 : std::min(smallestAngle(pa, pb, pc), smallestAngle(pb, pa, pd));
    const double after = std::min(smallestAngle(pa, pd, pc), smallestAngle(pb, pc, pd));
    if (!(after > before + kGain)) return false;
    // Nothing turns over: the new faces agree with the old ones, or, where one of those was turned
    // back over the mesh, with each other.
    const Vec3 n = nf + ng;
    if (turnedBefore ? n1.dot(n2) <= 0 : (n1.dot(n) <= 0 || n2.dot(n) <= 0)) return false;
    m_.faces[f] = {a, d, c};
    m_.faces[g] = {b, c, d};
    drop(a, g);
    drop(b, f);
    faces_[c].push_back(g);
    faces_[d].push_back(f);
    for (int x : {a, b, c, d}) touch(x);
    return true;
  }

  // Splits edge (a, b) between f = (a, b, c) and g = (b, a, d) at its midpoint m into (a, m, c),
  // (m, b, c), (b, m, d), (m, a, d); the two new faces are appended, flagged as patch faces.
  void split(int f, int g, int a, int b) {
    const int c = third(f, a, b), d = third(g, b, a);
    const int m = static_cast<int>(m_.positions.size());
    m_.positions.push_back(0.5 * (m_.positions[a] + m_.positions[b]));
    sigma_.push_back(0.5 * (sigma_[a] + sigma_[b]));
    faces_.emplace_back();
    const int f2 = static_cast<int>(m_.faces.size()), g2 = f2 + 1;
    m_.faces[f] = {a, m, c};
    m_.faces[g] = {b, m, d};
    m_.faces.push_back({m, b, c});
    m_.faces.push_back({m, a, d});
    patch_.push_back(1);
    patch_.push_back(1);
    drop(b, f);
    drop(a, g);
    faces_[b].push_back(f2);
    faces_[c].push_back(f2);
    faces_[a].push_back(g2);
    faces_[d].push_back(g2);
    faces_[m] = {f, g, f2, g2};
    for (int x : {a, b, c, d, m}) touch(x);
  }

  // Undoes the last split(f, g, a, b): f and g were `oldF` = (a, b, c) and `oldG` = (b, a, d).
  void unsplit(int f, int g, const Face& oldF, const Face& oldG) {
    const int f2 = static_cast<int>(m_.faces.size()) - 2, g2 = f2 + 1;  // (m, b, c) and (m, a, d)
    const int b = m_.faces[f2][1], c = m_.faces[f2][2], a = m_.faces[g2][1], d = m_.faces[g2][2];
    m_.faces[f] = oldF;
    m_.faces[g] = oldG;
    m_.faces.resize(f2);
    patch_.resize(f2);
    drop(b, f2);
    drop(c, f2);
    drop(a, g2);
    drop(d, g2);
    faces_[b].push_back(f);
    faces_[a].push_back(g);
    faces_.pop_back();
    m_.positions.pop_back();
    sigma_.pop_back();
    for (int x : {a, b, c, d}) touch(x);
  }

  // What changed when: a move of v, or a change of one of v's faces, changes the outcome for v, for
  // its neighbours and for the faces around them. Arrays only grow (a split that is undone leaves
  // its slots; the next split's touch makes them current).
  void grow() {
    if (stamp_.size() < m_.positions.size()) {
      stamp_.resize(m_.positions.size(), clock_);
      vLooked_.resize(m_.positions.size(), 0);
    }
    if (fLooked_.size() < m_.faces.size()) fLooked_.resize(m_.faces.size(), 0);
  }
  void touch(int v) {
    grow();
    ++clock_;
    stamp_[v] = clock_;
    for (int f : faces_[v])
      for (int x : m_.faces[f]) stamp_[x] = clock_;
  }

  // Face `face` no longer has corner v.
  void drop(int v, int face) { faces_[v].erase(std::find(faces_[v].begin(), faces_[v].end(), face)); }

  // The vertex of face f that is neither a nor b.
  int third(int f, int a, int b) const {
    for (int x : m_.faces[f])
      if (x != a && x != b) return x;
    return -1;
  }

  TriMesh& m_;
  std::vector<std::uint8_t>& patch_;
  std::vector<double>& sigma_;
  int firstNew_;
  double goodEnough_;  // vertices whose faces all have angles above this stay where they are
  bool finishing_;     // the last pass on a flowed patch: border apexes are searched finely
  std::vector<std::vector<int>> faces_;  // faceListsOf(): flips and splits remove faces from them
  long long clock_ = 1;  // counts changes; everything starts as changed (stamp 1, looked at 0)
  std::vector<long long> stamp_, vLooked_, fLooked_;
};

}  // namespace

int improvePatchAngles(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
                       double goodEnoughDegrees, int passes, bool finishing) {
  PatchAngles patch(mesh, patchFace, sigma, firstNew, goodEnoughDegrees, finishing);
  int changes = patch.splitEars();
  for (int pass = 0; pass < passes; ++pass) {
    const int made = patch.flipPass() + patch.movePass();
    changes += made;
    if (made == 0) break;
  }
  if (finishing) changes += patch.splitBorderApexes();
  return changes;
}

}  // namespace elastica
