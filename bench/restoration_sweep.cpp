// SPDX-License-Identifier: GPL-3.0-or-later
// Restoration at every hole size: on one real mesh, cut holes of growing border length around one
// point (a geodesic disc around the vertex nearest it, as many faces as give the cut's border the
// requested number of edges), fill each with `elastica fill`'s default and with CGAL's
// triangulate_refine_and_fair_hole, and score both against the surface that was cut away.
//
//   restoration_sweep MESH --center X Y Z --edges N1,N2,... [--subdivide L] [--name NAME] [--write-dir DIR]
//                     [--shape-tol T] [--stop-after refinement|biharmonic|flow]
//
// --shape-tol T sets the fill flow's FlowOptions::shapeTolerance (default: the fill's); --stop-after
// ends the fill after that stage (experiments: how close the bi-Laplace start alone comes). --subdivide L refines the mesh L times 1-to-4 first (midpoints: the shape stays the scan's), so
// that holes of thousands of border edges fit in it. Prints one Markdown table row per size:
// border edges (as cut), new vertices, time (best of runs within a second, one run above it),
// smallest patch angle and the bound the border itself sets (its smallest corner inside the hole),
// patch faces turned back over a neighbour (folds: normals more than 150° apart),
// RMS distances patch→truth and truth→patch in % of the bounding-box diagonal.
#include "geodesic_cut.h"
#include "guarded_main.h"
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

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

using namespace elastica;

namespace {

void writeMesh(const std::string& path, const TriMesh& m) {
  VcgMesh vm;
  fromTriMesh(m, vm);
  io::writePly(path, vm, io::PlyWriteOptions{});
}

struct Score {
  double ms = 0;
  int runs = 0, newVertices = 0, turned = 0;
  double angle = 0, there = 0, back = 0;
};

// Faces from `firstFace` on that lie turned back over a face sharing an edge with them (their
// normals more than 150° apart): a fold, which no angle or distance shows. (A crease of 120–150°
// can be the shape: a patch across a thin feature on a coarse mesh has some.)
int turnedFaces(const TriMesh& m, int firstFace) {
  const double kFoldCos = -std::sqrt(3.0) / 2;  // cos 150°
  auto normal = [&](int f) {
    const Face& t = m.faces[f];
    return (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).normalized();
  };
  auto key = [](int a, int b) { return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b)); };
  std::unordered_map<std::uint64_t, std::vector<int>> facesOnEdge;  // the new faces' edges
  for (int f = firstFace; f < m.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) facesOnEdge[key(m.faces[f][k], m.faces[f][(k + 1) % 3])];
  for (int f = 0; f < m.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto it = facesOnEdge.find(key(m.faces[f][k], m.faces[f][(k + 1) % 3]));
      if (it != facesOnEdge.end()) it->second.push_back(f);
    }
  std::vector<std::uint8_t> turned(m.faces.size(), 0);
  for (const auto& [edge, faces] : facesOnEdge)
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (normal(faces[i]).dot(normal(faces[j])) < kFoldCos) turned[faces[i]] = turned[faces[j]] = 1;
  return static_cast<int>(std::count(turned.begin() + firstFace, turned.end(), 1));
}

Score score(const test::Cut& cut, const std::function<void(TriMesh&)>& fill, double diagonal, TriMesh& result) {
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
  s.turned = turnedFaces(result, cut.holed.faceCount());
  s.there = 100 * bench::sampledDistance(patch, cut.truth, 4).rms / diagonal;
  s.back = 100 * bench::sampledDistance(cut.truth, patch, 4).rms / diagonal;
  return s;
}

}  // namespace

static int run(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH --center X Y Z --edges N1,N2,... [--subdivide L] [--name NAME] [--write-dir DIR] [--shape-tol T] [--stop-after refinement|biharmonic|flow]\n", argv[0]);
    return 2;
  }
  Vec3 center = Vec3::Zero();
  std::vector<int> sizes;
  int subdivide = 0;
  double shapeTolerance = HoleFillOptions::defaultFillFlow().shapeTolerance;
  std::string name = argv[1], writeDir;
  FillStage stopAfter = FillStage::Flow;
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
    } else if (a == "--shape-tol" && i + 1 < argc) {
      shapeTolerance = std::atof(argv[++i]);
    } else if (a == "--stop-after" && i + 1 < argc) {
      const std::string stage = argv[++i];
      if (stage == "refinement") stopAfter = FillStage::Refinement;
      else if (stage == "biharmonic") stopAfter = FillStage::Biharmonic;
      else if (stage == "flow") stopAfter = FillStage::Flow;
      else {
        std::fprintf(stderr, "restoration_sweep: --stop-after takes refinement, biharmonic or flow\n");
        return 2;
      }
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

  const std::vector<int> order = test::facesByDistance(full, center);
  for (int edges : sizes) {
    const test::Cut cut = test::cutWithBorder(full, order, edges);
    TriMesh ours, theirs;
    HoleFillOptions opt;
    opt.maxHoleEdges = 1000000;
    opt.flow.shapeTolerance = shapeTolerance;
    opt.stopAfter = stopAfter;
    HoleFillReport report;
    const Score e = score(cut, [&](TriMesh& m) { report = fillHoles(m, opt); }, diagonal, ours);
    double bound = 180;
    for (const HoleReport& h : report.holes) bound = std::min(bound, h.borderBoundDegrees);
    std::printf("| %s | %d | %d | %d | %.0f | %.1f° | %.1f° | %d | %.3f %% | %.3f %% |", name.c_str(), full.vertexCount(), cut.borderEdges,
                e.newVertices, e.ms, e.angle, bound, e.turned, e.there, e.back);
#ifdef ELASTICA_HAVE_CGAL
    const Score c = score(cut, [](TriMesh& m) { bench::cgalFillHoles(m); }, diagonal, theirs);
    std::printf(" %d | %.0f | %.1f | %.1f° | %d | %.3f %% | %.3f %% |", c.newVertices, c.ms, e.ms / c.ms, c.angle, c.turned, c.there, c.back);
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

int main(int argc, char** argv) { return bench::guardedMain("restoration_sweep", run, argc, argv); }
