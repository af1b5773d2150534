// Restoration at every hole size: on one real mesh, cut holes of growing border length around one
// point (a geodesic disc around the vertex nearest it, as many faces as give the cut's border the
// requested number of edges), fill each with `elastica fill`'s default and with CGAL's
// triangulate_refine_and_fair_hole, and score both against the surface that was cut away.
//
//   restoration_sweep MESH --center X Y Z --edges N1,N2,... [--subdivide L] [--name NAME] [--write-dir DIR]
//
// --subdivide L refines the mesh L times 1-to-4 first (midpoints: the shape stays the scan's), so
// that holes of thousands of border edges fit in it. Prints one Markdown table row per size:
// border edges (as cut), new vertices, time (best of runs within a second, one run above it),
// smallest patch angle and the bound the border itself sets (its smallest corner inside the hole),
// RMS distances patch→truth and truth→patch in % of the bounding-box diagonal.
#include "surface_distance.h"
#ifdef ELASTICA_HAVE_CGAL
#include "cgal_fill.h"
#endif

#include <elastica/hole_filling.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/mesh_quality.h>
#include <elastica/subdivision.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <map>
#include <sstream>
#include <string>

using namespace elastica;

namespace {

struct Cut {
  TriMesh holed, truth;
  int borderEdges = 0;
};

// Faces ordered by their geodesic distance from the vertex nearest `center` (Dijkstra along edges;
// a face is as far as its farthest vertex): cutting a prefix of this order cuts a geodesic disc,
// one hole however the surface bends (a ball would also cut through a nearby ear or leg).
std::vector<int> facesByDistance(const TriMesh& full, const Vec3& center) {
  const int nv = full.vertexCount();
  std::vector<std::vector<std::pair<int, double>>> edges(nv);
  for (const Face& t : full.faces)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const double l = (full.positions[a] - full.positions[b]).norm();
      edges[a].emplace_back(b, l);
      edges[b].emplace_back(a, l);
    }
  int seed = 0;
  for (int v = 1; v < nv; ++v)
    if ((full.positions[v] - center).squaredNorm() < (full.positions[seed] - center).squaredNorm()) seed = v;
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>> queue;
  dist[seed] = 0;
  queue.emplace(0.0, seed);
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    for (const auto& [w, l] : edges[v])
      if (d + l < dist[w]) queue.emplace(dist[w] = d + l, w);
  }
  std::vector<double> key(full.faces.size());
  for (std::size_t f = 0; f < full.faces.size(); ++f)
    key[f] = std::max({dist[full.faces[f][0]], dist[full.faces[f][1]], dist[full.faces[f][2]]});
  std::vector<int> order(full.faces.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  return order;
}

// The first `count` faces of `order` are cut away.
Cut cutFaces(const TriMesh& full, const std::vector<int>& order, int count) {
  std::vector<std::uint8_t> removed(full.faces.size(), 0), kept(full.faces.size(), 1);
  for (int i = 0; i < count; ++i) {
    removed[order[i]] = 1;
    kept[order[i]] = 0;
  }
  // Border edges of the cut: edges between a removed and a kept face.
  std::map<std::pair<int, int>, int> edgeSide;  // +1 per kept face, +100 per removed face
  for (std::size_t f = 0; f < full.faces.size(); ++f) {
    const Face& t = full.faces[f];
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
      edgeSide[{a, b}] += removed[f] ? 100 : 1;
    }
  }
  Cut cut;
  for (const auto& [edge, side] : edgeSide) cut.borderEdges += side == 101;
  cut.holed = bench::facesOf(full, kept);
  cut.truth = bench::facesOf(full, removed);
  return cut;
}

// The geodesic disc whose border has about `edges` edges (bisection on the number of faces cut:
// the border grows with it, not strictly).
Cut cutWithBorder(const TriMesh& full, const std::vector<int>& order, int edges) {
  int lo = 1, hi = full.faceCount() / 2;
  Cut best;
  best.borderEdges = -1;
  while (lo <= hi && std::abs(best.borderEdges - edges) > edges / 50) {
    const int mid = (lo + hi) / 2;
    Cut c = cutFaces(full, order, mid);
    (c.borderEdges < edges ? lo : hi) = c.borderEdges < edges ? mid + 1 : mid - 1;
    if (best.borderEdges < 0 || std::abs(c.borderEdges - edges) < std::abs(best.borderEdges - edges)) best = std::move(c);
  }
  return best;
}

void writeMesh(const std::string& path, const TriMesh& m) {
  VcgMesh vm;
  fromTriMesh(m, vm);
  io::writePly(path, vm, io::PlyWriteOptions{});
}

struct Score {
  double ms = 0;
  int runs = 0, newVertices = 0;
  double angle = 0, there = 0, back = 0;
};

Score score(const Cut& cut, const std::function<void(TriMesh&)>& fill, double diagonal, TriMesh& result) {
  Score s;
  double spent = 0;
  while (s.runs == 0 || (s.runs < 10 && spent + s.ms / 1e3 < 1.0)) {
    result = cut.holed;
    const auto start = std::chrono::steady_clock::now();
    fill(result);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    s.ms = s.runs++ == 0 ? 1e3 * sec : std::min(s.ms, 1e3 * sec);
    spent += sec;
  }
  std::vector<std::uint8_t> isNew(result.faces.size(), 0);
  for (int f = cut.holed.faceCount(); f < result.faceCount(); ++f) isNew[f] = 1;
  const TriMesh patch = bench::facesOf(result, isNew);
  s.newVertices = result.vertexCount() - cut.holed.vertexCount();
  s.angle = smallestAngleDegrees(result, cut.holed.faceCount());
  s.there = 100 * bench::sampledDistance(patch, cut.truth, 4).rms / diagonal;
  s.back = 100 * bench::sampledDistance(cut.truth, patch, 4).rms / diagonal;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH --center X Y Z --edges N1,N2,... [--subdivide L] [--name NAME] [--write-dir DIR]\n", argv[0]);
    return 2;
  }
  Vec3 center = Vec3::Zero();
  std::vector<int> sizes;
  int subdivide = 0;
  std::string name = argv[1], writeDir;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--center" && i + 3 < argc) {
      center = Vec3(std::atof(argv[i + 1]), std::atof(argv[i + 2]), std::atof(argv[i + 3]));
      i += 3;
    } else if (a == "--edges" && i + 1 < argc) {
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::atoi(item.c_str()));
    } else if (a == "--subdivide" && i + 1 < argc) {
      subdivide = std::atoi(argv[++i]);
    } else if (a == "--name" && i + 1 < argc) {
      name = argv[++i];
    } else if (a == "--write-dir" && i + 1 < argc) {
      writeDir = argv[++i];
    } else {
      std::fprintf(stderr, "restoration_sweep: unknown or incomplete argument %s\n", a.c_str());
      return 2;
    }
  }
  VcgMesh vm;
  io::readMesh(argv[1], vm);
  TriMesh full = toTriMesh(vm);
  for (int l = 0; l < subdivide; ++l) subdivideMidpoint(full);
  Vec3 lo = full.positions[0], hi = lo;
  for (const Vec3& p : full.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diagonal = (hi - lo).norm();

  const std::vector<int> order = facesByDistance(full, center);
  for (int edges : sizes) {
    const Cut cut = cutWithBorder(full, order, edges);
    TriMesh ours, theirs;
    HoleFillOptions opt;
    opt.maxHoleEdges = 1000000;
    HoleFillReport report;
    const Score e = score(cut, [&](TriMesh& m) { report = fillHoles(m, opt); }, diagonal, ours);
    double bound = 180;
    for (const HoleReport& h : report.holes) bound = std::min(bound, h.borderBoundDegrees);
    std::printf("| %s | %d | %d | %d | %.0f | %.1f° | %.1f° | %.3f %% | %.3f %% |", name.c_str(), full.vertexCount(), cut.borderEdges,
                e.newVertices, e.ms, e.angle, bound, e.there, e.back);
#ifdef ELASTICA_HAVE_CGAL
    const Score c = score(cut, [](TriMesh& m) { bench::cgalFillHoles(m); }, diagonal, theirs);
    std::printf(" %d | %.0f | %.1f | %.1f° | %.3f %% | %.3f %% |", c.newVertices, c.ms, e.ms / c.ms, c.angle, c.there, c.back);
#endif
    std::printf("\n");
    std::fflush(stdout);
    if (!writeDir.empty()) {
      const std::string stem = writeDir + "/" + name + "_" + std::to_string(cut.borderEdges);
      writeMesh(stem + "_holed.ply", cut.holed);
      writeMesh(stem + "_elastica.ply", ours);
      if (!theirs.faces.empty()) writeMesh(stem + "_cgal.ply", theirs);
    }
  }
  return 0;
}
