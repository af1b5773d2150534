// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/patch_remeshing.h"
#include "mesh/surface_projection.h"
#include "support/parallel.h"

#include <elastica/vertex_faces.h>

#include <algorithm>
#include <chrono>
#include <iterator>
#include <set>
#include <utility>

namespace elastica {
namespace {

constexpr double kSplitFactor = 4.0 / 3;     // Botsch & Kobbelt's thresholds: they make a split's
constexpr double kCollapseFactor = 4.0 / 5;  // halves and a collapse's result land between them
constexpr int kMaxSplitPasses = 16;          // each pass halves the longest edges; bounds a runaway
constexpr int kTargetValence = 6;
// A collapse or flip must keep every affected face turned the way it was, with margin: the new
// normal may turn by at most ~60° (cos 60° = 0.5) from the old one.
constexpr double kMinNormalCosine = 0.5;

Vec3 faceNormal(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }
// Whether a face whose (area-scaled) normal was `before` is still turned the same way, with margin.
bool turnsLittle(const Vec3& before, const Vec3& after) {
  return after.dot(before) > kMinNormalCosine * after.norm() * before.norm();
}

// The patch with per-vertex face lists, edited in place. Dead faces and vertices are marked and
// dropped by compact().
class PatchEditor {
 public:
  PatchEditor(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma,
              std::vector<std::uint8_t>& movable, double lengthScale, bool mayShrink, const SurfaceProjector* surface)
      : m_(mesh), patch_(patchFace), sigma_(sigma), movable_(movable), scale_(lengthScale), surface_(surface),
        faceAlive_(mesh.faces.size(), 1), vertexFaces_(faceListsOf(mesh)) {
    sharpDegree_.assign(m_.positions.size(), 0);
    if (surface_)
      for (const auto& [a, b] : sharpEdges(m_, surface_->featureAngleDegrees())) addSharp(a, b);
    sigma_.resize(m_.positions.size(), 0);
    movable_.resize(m_.positions.size(), 0);
    int patchSoFar = 0;
    for (int f = 0; f < m_.faceCount(); ++f) {
      if (patch_[f]) ++patchSoFar;
      else slotsBeforeOutside_ = patchSoFar;
    }
    livePatchFaces_ = patchSoFar;
    minPatchFaces_ = mayShrink ? 0 : slotsBeforeOutside_;
  }

  // The edges of the live patch faces, each once as (smaller, larger), in increasing order: vertex
  // by vertex, its larger neighbours across live patch faces (a sort per vertex, not one of every
  // edge twice: the whole list was 1 million pairs on the armadillo's 1,978-edge hole, sorted
  // some 40 times per remeshing).
  std::vector<std::pair<int, int>> patchEdges() const {
    std::vector<std::pair<int, int>> edges;
    std::vector<int> larger;
    for (int a = 0; a < m_.vertexCount(); ++a) {
      larger.clear();
      for (int f : vertexFaces_[a]) {
        if (!patch_[f]) continue;  // vertexFaces_ holds live faces only
        for (int b : m_.faces[f])
          if (b > a) larger.push_back(b);
      }
      std::sort(larger.begin(), larger.end());
      larger.erase(std::unique(larger.begin(), larger.end()), larger.end());
      for (int b : larger) edges.emplace_back(a, b);
    }
    return edges;
  }

  // The edges of the live patch faces at the vertices from `first` on, as patchEdges() lists them.
  std::vector<std::pair<int, int>> edgesAt(int first) const {
    std::vector<std::pair<int, int>> edges;
    for (int v = first; v < m_.vertexCount(); ++v)
      for (int f : vertexFaces_[v])
        if (patch_[f])
          for (int u : m_.faces[f])
            if (u != v) edges.push_back(std::minmax(u, v));
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
  }

  double length(int a, int b) const { return (m_.positions[a] - m_.positions[b]).norm(); }
  // The edge length wanted between a and b (their sigmas' mean times the options' lengthScale),
  // and the sigma a vertex made between them carries (without the scale).
  double target(int a, int b) const { return scale_ * sigmaBetween(a, b); }
  double sigmaBetween(int a, int b) const { return 0.5 * (sigma_[a] + sigma_[b]); }

  // The faces on edge (a, b): f0 = (a, b, c) and f1 = (b, a, d) in cyclic order. False unless the
  // edge exists with two faces, both in the patch (the patch's border is never edited).
  bool interiorEdge(int a, int b, int& f0, int& f1, int& c, int& d) const {
    f0 = f1 = -1;
    for (int f : vertexFaces_[a]) {
      const Face& t = m_.faces[f];
      for (int k = 0; k < 3; ++k) {
        if (t[k] != a) continue;
        if (t[(k + 1) % 3] == b) f0 = f, c = t[(k + 2) % 3];
        if (t[(k + 2) % 3] == b) f1 = f, d = t[(k + 1) % 3];
      }
    }
    return f0 >= 0 && f1 >= 0 && patch_[f0] && patch_[f1];
  }

  bool split(int a, int b) {
    int f0, f1, c = -1, d = -1;
    if (!interiorEdge(a, b, f0, f1, c, d)) return false;
    const int x = m_.vertexCount();
    const bool alongSharp = isSharp(a, b);
    Vec3 p = 0.5 * (m_.positions[a] + m_.positions[b]);
    if (surface_) p = placed(p, alongSharp, areaNormal(f0) + areaNormal(f1));
    m_.positions.push_back(p);
    sigma_.push_back(sigmaBetween(a, b));
    movable_.push_back(1);
    sharpDegree_.push_back(0);
    vertexFaces_.emplace_back();
    addFace({x, b, c});
    addFace({x, a, d});
    setFace(f0, {a, x, c});
    setFace(f1, {b, x, d});
    if (alongSharp) {
      removeSharp(a, b);
      addSharp(a, x);
      addSharp(x, b);
    }
    return true;
  }

  // Removes movable vertex a by joining it to movable vertex b, which moves to p, if that keeps the patch
  // a manifold disk with no face turned over and no edge longer than kSplitFactor · target.
  bool collapse(int a, int b, const Vec3& p) {
    if (!movable_[a] || !movable_[b] || livePatchFaces_ - 2 < minPatchFaces_) return false;
    int f0, f1, c = -1, d = -1;
    if (!interiorEdge(a, b, f0, f1, c, d)) return false;
    // Link condition: a and b share exactly the neighbours c and d; c and d keep three faces.
    std::vector<int> na = neighbours(a), nb = neighbours(b), common;
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
    if (common.size() != 2 || vertexFaces_[c].size() <= 3 || vertexFaces_[d].size() <= 3) return false;
    if (!keepsSharpLines(a, b, p)) return false;
    const double s = sigmaBetween(a, b);
    for (int v : {a, b}) {
      for (int f : vertexFaces_[v]) {
        if (f == f0 || f == f1) continue;
        for (int u : m_.faces[f])
          if (u != v && (p - m_.positions[u]).norm() > kSplitFactor * scale_ * 0.5 * (s + sigma_[u])) return false;
        if (!turnsLittle(normalOf(f, v, m_.positions[v]), normalOf(f, v, p))) return false;
      }
    }
    killFace(f0);
    killFace(f1);
    std::vector<int> sharpAtA;  // a's sharp lines go on from b
    for (int u : na)
      if (isSharp(a, u)) sharpAtA.push_back(u);
    for (int u : sharpAtA) {
      removeSharp(a, u);
      if (u != b) addSharp(b, u);
    }
    for (int f : vertexFaces_[a]) {
      for (int& v : m_.faces[f]) v = v == a ? b : v;
      vertexFaces_[b].push_back(f);
    }
    vertexFaces_[a].clear();
    m_.positions[b] = p;
    sigma_[b] = s;
    return true;
  }

  // A short edge: two movable vertices meet at its midpoint; a movable vertex too close to a fixed
  // one (which stays) is joined, at its place, to one of its other movable neighbours instead.
  bool collapseShort(int a, int b) {
    if (surface_) return collapseOnSurface(a, b);
    if (movable_[a] && movable_[b]) return collapse(a, b, 0.5 * (m_.positions[a] + m_.positions[b]));
    const int v = movable_[a] ? a : b;
    if (!movable_[v]) return false;
    for (int w : neighbours(v))
      if (movable_[w] && collapse(v, w, m_.positions[w])) return true;
    return false;
  }

  // collapseShort on a surface to keep: one end joins the other, at the midpoint (put back on the
  // surface) or, where only the kept end lies on a sharp line or it is a corner, at the kept end.
  bool collapseOnSurface(int a, int b) {
    for (const auto& [r, k] : {std::pair(a, b), std::pair(b, a)}) {
      if (!movable_[r] || !movable_[k] || corner(r)) continue;
      Vec3 p = m_.positions[k];
      if (sharpDegree_[k] == 0 || (sharpDegree_[r] == 2 && !corner(k))) {
        Vec3 n = Vec3::Zero();
        for (int f : vertexFaces_[r]) n += areaNormal(f);
        for (int f : vertexFaces_[k]) n += areaNormal(f);
        p = placed(0.5 * (m_.positions[r] + m_.positions[k]), sharpDegree_[r] == 2, n);
      }
      if (collapse(r, k, p)) return true;
    }
    return false;
  }

  // Flips (a, b) to (c, d) where that lowers Σ (valence − 6)² over the four vertices.
  bool flipForValence(int a, int b) {
    int f0, f1, c = -1, d = -1;
    if (!interiorEdge(a, b, f0, f1, c, d) || c == d || hasEdge(c, d) || isSharp(a, b)) return false;
    const int va = valence(a), vb = valence(b), vc = valence(c), vd = valence(d);
    if (va <= 3 || vb <= 3) return false;
    auto dev = [](int v) { return (v - kTargetValence) * (v - kTargetValence); };
    if (dev(va - 1) + dev(vb - 1) + dev(vc + 1) + dev(vd + 1) >= dev(va) + dev(vb) + dev(vc) + dev(vd)) return false;
    const auto& P = m_.positions;
    const Vec3 n0 = faceNormal(P[a], P[b], P[c]), n1 = faceNormal(P[b], P[a], P[d]);
    const Vec3 old = n0.normalized() + n1.normalized();
    for (const Vec3& n : {faceNormal(P[c], P[a], P[d]), faceNormal(P[d], P[b], P[c])})
      if (!turnsLittle(old, n)) return false;
    setFace(f0, {c, a, d});
    setFace(f1, {d, b, c});
    return true;
  }

  // Moves each movable vertex toward the mean of its neighbours, within the tangent plane of its
  // area-weighted normal (so the patch keeps its shape to first order). One Jacobi pass (each
  // vertex reads the positions before the pass only, so the vertices run in parallel and the
  // result does not depend on the thread count); a move that would turn one of the vertex's faces
  // over (against the neighbours' current positions) is halved until it does not, or dropped.
  // Parallel since relaxing was half of the remeshing to the border's density on the
  // armadillo's 1,978-edge hole (3.2 s of 7.1 s, 25 passes over 190,000 vertices). The passes of
  // one round share the neighbour lists (relaxPasses() builds them once): sorting each vertex's
  // ring anew in every pass was a third of the relaxation.
  void relaxPasses(int passes) {
    if (passes <= 0) return;
    const int nv = m_.vertexCount();
    ringOffset_.assign(nv + 1, 0);
    ringVertex_.clear();
    std::vector<int> ring;
    for (int v = 0; v < nv; ++v) {
      if (movable_[v] && !vertexFaces_[v].empty()) {
        neighbours(v, ring);
        ringVertex_.insert(ringVertex_.end(), ring.begin(), ring.end());
      }
      ringOffset_[v + 1] = static_cast<int>(ringVertex_.size());
    }
    for (int k = 0; k < passes; ++k) relax();
  }

  void relax() {
    next_ = m_.positions;
    // Each face's normal at the pass's start, once (each of its corners read it up to five times).
    faceNormal_.resize(m_.faces.size());
    parallelFor(m_.faceCount(), [&](int f) {
      const Face& t = m_.faces[f];
      faceNormal_[f] = faceNormal(m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]);
    });
    parallelFor(m_.vertexCount(), [&](int v) {
      if (!movable_[v] || vertexFaces_[v].empty() || corner(v)) return;
      Vec3 n = Vec3::Zero();
      for (int f : vertexFaces_[v]) n += faceNormal_[f];
      Vec3 delta = Vec3::Zero();
      if (sharpDegree_[v] == 2) {
        // Along its sharp line: toward the midpoint of its two neighbours on the line.
        for (int k = ringOffset_[v]; k < ringOffset_[v + 1]; ++k)
          if (isSharp(v, ringVertex_[k])) delta += 0.5 * (m_.positions[ringVertex_[k]] - m_.positions[v]);
      } else {
        Vec3 c = Vec3::Zero();
        for (int k = ringOffset_[v]; k < ringOffset_[v + 1]; ++k) c += m_.positions[ringVertex_[k]];
        delta = c / static_cast<double>(ringOffset_[v + 1] - ringOffset_[v]) - m_.positions[v];
        const double nn = n.squaredNorm();
        if (nn > 0) delta -= delta.dot(n) / nn * n;
      }
      auto keepsTurned = [&](const Vec3& p) {
        for (int f : vertexFaces_[v])
          if (!turnsLittle(faceNormal_[f], normalOf(f, v, p))) return false;
        return true;
      };
      for (int halving = 0; halving < 4; ++halving, delta *= 0.5) {
        Vec3 p = m_.positions[v] + delta;
        if (surface_) {
          const Vec3 moved = p;
          p = placed(moved, sharpDegree_[v] == 2, n);
          if ((p - moved).norm() > delta.norm()) continue;  // onto another sheet, or off the line
        }
        if (keepsTurned(p)) {
          next_[v] = p;
          break;
        }
      }
    });
    m_.positions.swap(next_);
  }

  // Drops dead faces and dead vertices (compactFaces(), then the vertices' rule below).
  void compact() {
    compactFaces();
    compactVertices();
  }

 private:
  // Drops dead faces: while the patch has live faces for its slots before the last face outside
  // it, by filling the dead slots with faces from the end (no face outside moves); otherwise (only
  // with regionMayShrink) every live face moves down, keeping its order.
  void compactFaces() {
    if (livePatchFaces_ < slotsBeforeOutside_) {
      int next = 0;
      for (int f = 0; f < m_.faceCount(); ++f) {
        if (!faceAlive_[f]) continue;
        m_.faces[next] = m_.faces[f];
        patch_[next++] = patch_[f];
      }
      m_.faces.resize(next);
      patch_.resize(next);
      return;
    }
    int last = m_.faceCount() - 1;
    for (int s = 0; s < m_.faceCount(); ++s) {
      if (faceAlive_[s]) continue;
      while (last > s && !faceAlive_[last]) --last;
      if (last <= s) break;
      m_.faces[s] = m_.faces[last];
      patch_[s] = patch_[last];
      faceAlive_[s] = 1;
      faceAlive_[last--] = 0;
    }
    const int liveFaces = static_cast<int>(std::count(faceAlive_.begin(), faceAlive_.end(), 1));
    m_.faces.resize(liveFaces);
    patch_.resize(liveFaces);
  }

  void compactVertices() {
    // Fixed vertices keep their indices; the live movable ones fill the other slots in their
    // order (with every movable vertex after every fixed one, as in a hole's patch, that is
    // moving later vertices down). If too many movable vertices died for that (a fixed vertex
    // would be past the end), every live vertex moves down instead, fixed ones keeping their order.
    const int n = m_.vertexCount();
    int live = 0, lastFixed = -1;
    for (int v = 0; v < n; ++v) {
      if (!(movable_[v] && vertexFaces_[v].empty())) ++live;
      if (!movable_[v]) lastFixed = v;
    }
    std::vector<int> index(n, -1);
    if (lastFixed < live) {
      for (int v = 0; v < n; ++v)
        if (!movable_[v]) index[v] = v;
      int slot = 0;
      for (int v = 0; v < n; ++v) {
        if (!movable_[v] || vertexFaces_[v].empty()) continue;
        while (slot < n && slot <= lastFixed && !movable_[slot]) ++slot;
        index[v] = slot++;
      }
    } else {
      int next = 0;
      for (int v = 0; v < n; ++v)
        if (!(movable_[v] && vertexFaces_[v].empty())) index[v] = next++;
    }
    std::vector<Vec3> positions(live);
    std::vector<std::uint8_t> movable(live);
    std::vector<double> sigma(live);
    for (int v = 0; v < n; ++v) {
      if (index[v] < 0) continue;
      positions[index[v]] = m_.positions[v];
      movable[index[v]] = movable_[v];
      sigma[index[v]] = sigma_[v];
    }
    m_.positions.swap(positions);
    movable_.swap(movable);
    sigma_.swap(sigma);
    for (Face& t : m_.faces)
      for (int& v : t) v = index[v];
  }

  void addFace(const Face& t) {
    const int f = m_.faceCount();
    m_.faces.push_back(t);
    patch_.push_back(1);
    faceAlive_.push_back(1);
    for (int v : t) vertexFaces_[v].push_back(f);
    ++livePatchFaces_;
  }
  void setFace(int f, const Face& t) {
    for (int v : m_.faces[f]) eraseFrom(vertexFaces_[v], f);
    m_.faces[f] = t;
    for (int v : t) vertexFaces_[v].push_back(f);
  }
  void killFace(int f) {
    for (int v : m_.faces[f]) eraseFrom(vertexFaces_[v], f);
    faceAlive_[f] = 0;
    --livePatchFaces_;
  }
  static void eraseFrom(std::vector<int>& list, int f) { list.erase(std::find(list.begin(), list.end(), f)); }

  // p put on the surface to keep: on its sharp edges if `alongSharp`, else on its closest face
  // turned toward `normal`; p itself if the surface has no such place.
  Vec3 placed(const Vec3& p, bool alongSharp, const Vec3& normal) const {
    Vec3 q = p;
    if (alongSharp ? surface_->projectOnSharpEdge(p, q) : surface_->project(p, normal, q)) return q;
    return p;
  }
  Vec3 areaNormal(int f) const {
    const Face& t = m_.faces[f];
    return faceNormal(m_.positions[t[0]], m_.positions[t[1]], m_.positions[t[2]]);
  }

  // The sharp edges (PatchRemeshingOptions::surface) and how many meet at each vertex: 2 on a
  // sharp line, other counts at a corner (where lines meet or end), which never moves.
  bool isSharp(int a, int b) const { return !sharp_.empty() && sharp_.count(std::minmax(a, b)) > 0; }
  bool corner(int v) const { return sharpDegree_[v] != 0 && sharpDegree_[v] != 2; }
  void addSharp(int a, int b) {
    if (sharp_.insert(std::minmax(a, b)).second) ++sharpDegree_[a], ++sharpDegree_[b];
  }
  void removeSharp(int a, int b) {
    if (sharp_.erase(std::minmax(a, b)) > 0) --sharpDegree_[a], --sharpDegree_[b];
  }
  // Whether joining a to b at p keeps the sharp lines: a off every line (b then stays where it is
  // if it is on one), or a on one line running on to b (a corner b stays where it is).
  bool keepsSharpLines(int a, int b, const Vec3& p) const {
    if (!surface_) return true;
    if (sharpDegree_[a] == 0) return sharpDegree_[b] == 0 || p == m_.positions[b];
    if (sharpDegree_[a] != 2 || !isSharp(a, b)) return false;
    return !corner(b) || p == m_.positions[b];
  }

  // The normal (area-scaled) of face f with vertex v at p.
  Vec3 normalOf(int f, int v, const Vec3& p) const {
    const Face& t = m_.faces[f];
    Vec3 q[3];
    for (int k = 0; k < 3; ++k) q[k] = t[k] == v ? p : m_.positions[t[k]];
    return faceNormal(q[0], q[1], q[2]);
  }

  std::vector<int> neighbours(int v) const {
    std::vector<int> out;
    neighbours(v, out);
    return out;
  }
  // The same into `out` (no allocation per vertex: it showed in profiles of large patches).
  void neighbours(int v, std::vector<int>& out) const {
    out.clear();
    for (int f : vertexFaces_[v])
      for (int u : m_.faces[f])
        if (u != v) out.push_back(u);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
  // Every patch vertex has a closed fan in the piece of mesh the caller hands over (the patch's
  // border keeps its whole ring), so its valence is its face count.
  int valence(int v) const { return static_cast<int>(vertexFaces_[v].size()); }
  bool hasEdge(int a, int b) const {
    for (int f : vertexFaces_[a]) {
      const Face& t = m_.faces[f];
      if (t[0] == b || t[1] == b || t[2] == b) return true;
    }
    return false;
  }

  TriMesh& m_;
  std::vector<std::uint8_t>& patch_;
  std::vector<double>& sigma_;
  std::vector<std::uint8_t>& movable_;
  double scale_;
  const SurfaceProjector* surface_;
  std::set<std::pair<int, int>> sharp_;  // the sharp edges, as (smaller, larger)
  std::vector<int> sharpDegree_;
  std::vector<std::uint8_t> faceAlive_;
  std::vector<std::vector<int>> vertexFaces_;  // faceListsOf(): collapses and flips remove faces from them
  std::vector<Vec3> next_;  // relax()'s new positions, reused
  std::vector<int> ringOffset_, ringVertex_;  // relaxPasses()' neighbour lists (CSR)
  std::vector<Vec3> faceNormal_;              // relax()'s face normals at the pass's start
  // compact() refills dead slots from the end of the face list: while the patch keeps at least as
  // many faces as it has slots before the last face outside it, no face outside it moves. Collapses
  // keep it so (minPatchFaces_) unless the region may shrink.
  int slotsBeforeOutside_ = 0, minPatchFaces_ = 0, livePatchFaces_ = 0;
};

}  // namespace

void remeshPatch(TriMesh& mesh, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
                 const PatchRemeshingOptions& opt) {
  std::vector<std::uint8_t> movable(mesh.positions.size(), 0);
  std::fill(movable.begin() + std::min<std::size_t>(std::max(firstNew, 0), movable.size()), movable.end(), 1);
  remeshRegion(mesh, patchFace, sigma, movable, opt);
}

bool remeshRegion(TriMesh& mesh, std::vector<std::uint8_t>& regionFace, std::vector<double>& sigma,
                  std::vector<std::uint8_t>& movable, const PatchRemeshingOptions& opt) {
  PatchEditor patch(mesh, regionFace, sigma, movable, opt.lengthScale, opt.regionMayShrink, opt.surface);
  bool withinLimit = true;
  for (int round = 0; round < opt.iterations && std::chrono::steady_clock::now() < opt.deadline; ++round) {
    // A split pass changes no length and no edge's faces' flags: the next pass can only split
    // an edge at a vertex the pass made, and looks at those alone (in the same order).
    std::vector<std::pair<int, int>> edges = patch.patchEdges();
    for (int pass = 0; pass < kMaxSplitPasses; ++pass) {
      const int made = mesh.vertexCount();
      bool any = false;
      for (const auto& [a, b] : edges) {
        if (opt.maxVertices > 0 && mesh.vertexCount() >= opt.maxVertices) {
          withinLimit = false;
          break;
        }
        if (patch.length(a, b) > kSplitFactor * patch.target(a, b)) any = patch.split(a, b) || any;
      }
      if (!any) break;
      edges = patch.edgesAt(made);
    }
    for (const auto& [a, b] : patch.patchEdges())
      if (patch.length(a, b) < kCollapseFactor * patch.target(a, b)) patch.collapseShort(a, b);
    for (const auto& [a, b] : patch.patchEdges()) patch.flipForValence(a, b);
    patch.relaxPasses(opt.relaxPasses);
  }
  patch.compact();
  return withinLimit;
}

}  // namespace elastica
