// SPDX-License-Identifier: GPL-3.0-or-later
// Many holes in a big scan: cut geodesic discs of varied border lengths at spread-out points of a
// real mesh (refined 1-to-4 at its edge midpoints to the size of a modern scan), fill them all with
// fillHoles' defaults, and measure the fill's time and peak memory against the holes' size and the
// mesh's own memory.
//
//   scan_holes_bench MESH [--subdivide L] [--holes N] [--edges MIN,MAX] [--name NAME] [--write OUT.bin]
//                    [--write-holed HOLED.ply]
//   scan_holes_bench --header          the table's header (two lines)
//
// Prints one Markdown table row: vertices of the holed scan, holes found and filled, their border
// edges, new vertices, the fill's seconds (all of it, inside the holes, outside them: the
// whole-mesh passes), milliseconds per thousand new vertices (and a least-squares line over the
// holes), the mesh's bytes, the fill's peak resident memory above the mesh, that peak (mesh
// included) over the input's and over the output's bytes, and the border edges left open.
// --write keeps the filled mesh (raw: counts, then positions and faces as in memory); --write-holed
// the holed scan as binary PLY (to time `elastica fill` on it with /usr/bin/time -v).
//
// The fill runs in a child process (this program again, `--fill FILE`) that holds nothing but the
// holed mesh: the cutter's own arrays would otherwise stay in the allocator's heap and hide what
// the fill allocates. The child resets the kernel's peak-RSS mark (/proc/self/clear_refs) just
// before fillHoles and reads it (VmHWM) just after.
#include "guarded_main.h"
#include "surface_distance.h"

#include <elastica/hole_filling.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/subdivision.h>
#include <elastica/topology.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>
#include <elastica/vertex_faces.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace elastica;

namespace {

// ------------------------------------------------------------------ memory of this process

long statusKiB(const char* field) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind(field, 0) == 0) return std::atol(line.c_str() + std::strlen(field));
  return -1;
}

// Sets the peak resident set (VmHWM) to the current one (Linux ≥ 4.0).
bool resetPeakRss() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// ------------------------------------------------------------------ the holed mesh on disk

void writeRaw(const std::string& path, const TriMesh& m) {
  std::ofstream out(path, std::ios::binary);
  const std::int64_t nv = m.vertexCount(), nf = m.faceCount();
  out.write(reinterpret_cast<const char*>(&nv), sizeof nv);
  out.write(reinterpret_cast<const char*>(&nf), sizeof nf);
  out.write(reinterpret_cast<const char*>(m.positions.data()), static_cast<std::streamsize>(nv * sizeof(Vec3)));
  out.write(reinterpret_cast<const char*>(m.faces.data()), static_cast<std::streamsize>(nf * sizeof(Face)));
  if (!out) throw std::runtime_error("cannot write " + path);
}

TriMesh readRaw(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::int64_t nv = 0, nf = 0;
  in.read(reinterpret_cast<char*>(&nv), sizeof nv);
  in.read(reinterpret_cast<char*>(&nf), sizeof nf);
  TriMesh m;
  m.positions.resize(nv);
  m.faces.resize(nf);
  in.read(reinterpret_cast<char*>(m.positions.data()), static_cast<std::streamsize>(nv * sizeof(Vec3)));
  in.read(reinterpret_cast<char*>(m.faces.data()), static_cast<std::streamsize>(nf * sizeof(Face)));
  if (!in) throw std::runtime_error("cannot read " + path);
  return m;
}

// ------------------------------------------------------------------ cutting the holes

// Seeds spread over the surface: farthest-point sampling (Euclidean), from vertex 0.
std::vector<int> spreadSeeds(const TriMesh& m, int count) {
  std::vector<double> nearest(m.positions.size(), std::numeric_limits<double>::infinity());
  std::vector<int> seeds;
  int next = 0;
  for (int s = 0; s < count; ++s) {
    seeds.push_back(next);
    const Vec3 p = m.positions[next];
    double far = -1;
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      nearest[v] = std::min(nearest[v], (m.positions[v] - p).squaredNorm());
      if (nearest[v] > far) {
        far = nearest[v];
        next = static_cast<int>(v);
      }
    }
  }
  return seeds;
}

// Cuts a geodesic disc around `seed`: faces in the order Dijkstra (along edges) completes them (a
// face is as far as its farthest vertex; the order restoration_sweep cuts in) until the cut's
// border has `edges` edges. Faces touching a `taken` vertex (an earlier hole and the ring around
// it) are never cut, so the holes stay apart. Marks the cut faces in `removed` and returns the
// border edge count reached.
int cutDisc(const TriMesh& m, const VertexFaces& vf, int seed, int edges, std::vector<std::uint8_t>& removed,
            std::vector<std::uint8_t>& taken, std::vector<double>& dist, std::vector<std::uint8_t>& settled) {
  std::vector<int> touched{seed}, cut;
  std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int>>, std::greater<>> queue;
  dist[seed] = 0;
  queue.emplace(0.0, seed);
  // The face across edge (a, b) from face f, or -1.
  auto across = [&](int f, int a, int b) {
    for (int g : vf.faces(a)) {
      if (g == f) continue;
      const Face& t = m.faces[g];
      if (t[0] == b || t[1] == b || t[2] == b) return g;
    }
    return -1;
  };
  int border = 0;
  while (!queue.empty() && border < edges) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v] || settled[v]) continue;
    settled[v] = 1;
    for (int f : vf.faces(v)) {
      if (border >= edges) break;
      const Face& t = m.faces[f];
      if (removed[f] || !settled[t[0]] || !settled[t[1]] || !settled[t[2]]) continue;
      if (taken[t[0]] || taken[t[1]] || taken[t[2]]) continue;
      removed[f] = 1;
      cut.push_back(f);
      for (int e = 0; e < 3; ++e) {
        const int g = across(f, t[e], t[(e + 1) % 3]);
        border += g >= 0 && removed[g] ? -1 : 1;
      }
    }
    for (int f : vf.faces(v)) {
      for (int w : m.faces[f]) {
        if (taken[w]) continue;  // a wall: the disc does not wrap around an earlier hole
        const double l = d + (m.positions[w] - m.positions[v]).norm();
        if (l < dist[w]) {
          if (dist[w] == std::numeric_limits<double>::infinity()) touched.push_back(w);
          dist[w] = l;
          queue.emplace(l, w);
        }
      }
    }
  }
  for (int v : touched) {
    dist[v] = std::numeric_limits<double>::infinity();
    settled[v] = 0;
  }
  // Where the disc's border passes twice through a vertex (the cut faces around it form two fans
  // or more), the fill would skip the hole: cut the vertex's whole fan, and look again around it.
  std::vector<int> work;
  for (int f : cut) work.insert(work.end(), m.faces[f].begin(), m.faces[f].end());
  while (!work.empty()) {
    const int v = work.back();
    work.pop_back();
    int changes = 0;  // edges at v between a cut face and a kept one
    for (int f : vf.faces(v)) {
      for (int x : m.faces[f]) {
        if (x == v) continue;
        const int g = across(f, v, x);
        changes += g >= 0 && f < g && removed[f] != removed[g];
      }
    }
    if (changes <= 2) continue;
    for (int f : vf.faces(v)) {
      if (removed[f]) continue;
      removed[f] = 1;
      cut.push_back(f);
      work.insert(work.end(), m.faces[f].begin(), m.faces[f].end());
    }
  }
  border = 0;
  for (int f : cut)
    for (int e = 0; e < 3; ++e) {
      const int g = across(f, m.faces[f][e], m.faces[f][(e + 1) % 3]);
      border += g < 0 || !removed[g];
    }
  // The hole and one ring of faces around it are off limits to the next holes.
  for (int f : cut)
    for (int v : m.faces[f])
      for (int g : vf.faces(v))
        for (int w : m.faces[g]) taken[w] = 1;
  return border;
}

// ------------------------------------------------------------------ the fill (child process)

// Prints one line: key=value pairs for the parent.
int fillOnly(const std::string& path, const std::string& writePath) {
  TriMesh mesh = readRaw(path);
  const std::size_t holedVertices = mesh.positions.size();
  const double meshBytes = mesh.positions.capacity() * sizeof(Vec3) + mesh.faces.capacity() * sizeof(Face);
  const long rssBefore = statusKiB("VmRSS:");
  const bool peakReset = resetPeakRss();
  const auto start = std::chrono::steady_clock::now();
  const HoleFillReport r = fillHoles(mesh, {});
  const double fillSeconds = seconds(start);
  const long peak = statusKiB("VmHWM:");
  const double outputBytes = mesh.positions.size() * sizeof(Vec3) + mesh.faces.size() * sizeof(Face);

  int filled = 0, minEdges = std::numeric_limits<int>::max(), maxEdges = 0;
  long long borderEdges = 0, newVertices = 0;
  double inHoles = 0;
  // Least squares seconds = a + b · new vertices over the holes.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const bool verbose = std::getenv("SCAN_HOLES_BENCH_VERBOSE") != nullptr;
  for (const HoleReport& h : r.holes) {
    if (verbose)
      std::fprintf(stderr, "hole: %d border edges, %s, %d new vertices, %.3f s %s\n", h.borderEdges, h.filled ? "filled" : "open",
                   h.newVertices, h.seconds, h.reason.c_str());
    filled += h.filled;
    minEdges = std::min(minEdges, h.borderEdges);
    maxEdges = std::max(maxEdges, h.borderEdges);
    borderEdges += h.borderEdges;
    newVertices += h.newVertices;
    inHoles += h.seconds;
    sx += h.newVertices;
    sy += h.seconds;
    sxx += double(h.newVertices) * h.newVertices;
    sxy += h.newVertices * h.seconds;
  }
  const double n = static_cast<double>(r.holes.size());
  const double slope = n > 1 ? (n * sxy - sx * sy) / (n * sxx - sx * sx) : 0, intercept = n > 0 ? (sy - slope * sx) / n : 0;
  const Topology topo(mesh.vertexCount(), mesh.faces);
  std::printf("vertices=%d holes=%zu filled=%d minEdges=%d maxEdges=%d borderEdges=%lld newVertices=%lld fill=%.3f inHoles=%.3f "
              "slope=%.6g intercept=%.6g meshMiB=%.1f outputMiB=%.1f rssBeforeMiB=%.1f peakMiB=%.1f peakReset=%d openEdges=%d\n",
              static_cast<int>(holedVertices), r.holes.size(), filled, r.holes.empty() ? 0 : minEdges, maxEdges, borderEdges, newVertices, fillSeconds, inHoles,
              slope, intercept, meshBytes / 1048576, outputBytes / 1048576, rssBefore / 1024.0, peak / 1024.0, peakReset ? 1 : 0,
              topo.boundaryEdgeCount());
  if (!writePath.empty()) writeRaw(writePath, mesh);
  return 0;
}

double field(const std::string& line, const std::string& key) {
  const auto at = line.find(key + "=");
  return at == std::string::npos ? NAN : std::atof(line.c_str() + at + key.size() + 1);
}

}  // namespace

static int run(int argc, char** argv) {
  if (argc >= 3 && std::strcmp(argv[1], "--fill") == 0) return fillOnly(argv[2], argc >= 4 ? argv[3] : "");
  if (argc == 2 && std::strcmp(argv[1], "--header") == 0) {
    std::printf("| scan | vertices | holes found / filled | border edges min–max (total) | new vertices | fill s | in holes s | "
                "outside holes s | ms per 1k new vertices (line over the holes) | mesh MiB | fill's peak above the mesh MiB | "
                "peak / input | peak / output | open edges |\n");
    std::printf("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    return 0;
  }
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MESH [--subdivide L] [--holes N] [--edges MIN,MAX] [--name NAME] [--write OUT.bin] [--write-holed HOLED.ply]\n", argv[0]);
    return 2;
  }
  int subdivide = 0, holes = 200, minEdges = 10, maxEdges = 300;
  std::string name = argv[1], writePath, holedPly;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--subdivide" && i + 1 < argc) {
      subdivide = std::atoi(argv[++i]);
    } else if (a == "--holes" && i + 1 < argc) {
      holes = std::atoi(argv[++i]);
    } else if (a == "--edges" && i + 1 < argc) {
      if (std::sscanf(argv[++i], "%d,%d", &minEdges, &maxEdges) != 2) minEdges = -1;
    } else if (a == "--name" && i + 1 < argc) {
      name = argv[++i];
    } else if (a == "--write" && i + 1 < argc) {
      writePath = argv[++i];
    } else if (a == "--write-holed" && i + 1 < argc) {
      holedPly = argv[++i];
    } else {
      std::fprintf(stderr, "scan_holes_bench: unknown or incomplete argument %s\n", a.c_str());
      return 2;
    }
  }
  if (holes < 1 || minEdges < 3 || maxEdges < minEdges) {
    std::fprintf(stderr, "scan_holes_bench: need --holes >= 1 and 3 <= MIN <= MAX\n");
    return 2;
  }

  std::string holedPath;
  {
    TriMesh full;
    {
      VcgMesh vm;
      io::readMesh(argv[1], vm);
      full = toTriMesh(vm);
    }
    for (int l = 0; l < subdivide; ++l) subdivideMidpoint(full);
    // Border lengths spread evenly on a log scale from MIN to MAX, dealt to the seeds in a fixed
    // shuffled order (large and small holes side by side).
    std::vector<int> sizes(holes);
    for (int i = 0; i < holes; ++i)
      sizes[i] = static_cast<int>(std::lround(minEdges * std::pow(double(maxEdges) / minEdges, holes > 1 ? double(i) / (holes - 1) : 0)));
    std::shuffle(sizes.begin(), sizes.end(), std::mt19937(42));
    const VertexFaces vf(full.vertexCount(), full.faces);
    const std::vector<int> seeds = spreadSeeds(full, holes);
    std::vector<std::uint8_t> removed(full.faces.size(), 0), taken(full.positions.size(), 0), settled(full.positions.size(), 0);
    std::vector<double> dist(full.positions.size(), std::numeric_limits<double>::infinity());
    for (int i = 0; i < holes; ++i) {
      if (taken[seeds[i]]) continue;
      cutDisc(full, vf, seeds[i], sizes[i], removed, taken, dist, settled);
    }
    for (std::uint8_t& f : removed) f = !f;
    TriMesh holed = bench::facesOf(full, removed);  // the faces kept
    holed.positions.shrink_to_fit();
    holed.faces.shrink_to_fit();
    holedPath = "/tmp/scan_holes_bench_" + std::to_string(getpid()) + ".bin";
    writeRaw(holedPath, holed);
    if (!holedPly.empty()) io::writePly(holedPly, holed, {}, /*binary=*/true);
  }
  // The fill, alone in a fresh process.
  std::string command = "'" + std::string(argv[0]) + "' --fill " + holedPath;
  if (!writePath.empty()) command += " '" + writePath + "'";
  FILE* child = popen(command.c_str(), "r");
  std::string line;
  char buffer[4096];
  while (child && std::fgets(buffer, sizeof buffer, child)) line += buffer;
  const int status = child ? pclose(child) : -1;
  std::remove(holedPath.c_str());
  if (status != 0 || line.find("holes=") == std::string::npos) {
    std::fprintf(stderr, "scan_holes_bench: the fill failed (%d): %s\n", status, line.c_str());
    return 1;
  }
  const double fill = field(line, "fill"), inHoles = field(line, "inHoles"), newVertices = field(line, "newVertices");
  const double mesh = field(line, "meshMiB"), output = field(line, "outputMiB");
  const double extra = field(line, "peakMiB") - field(line, "rssBeforeMiB");
  // The columns of --header.
  std::printf("| %s | %.0f | %.0f / %.0f | %.0f–%.0f (%.0f) | %.0f | %.1f | %.1f | %.2f | %.1f (%.0f ms + %.2f ms/1k) | %.0f | %.0f | %.2f× | %.2f× | %.0f |\n",
              name.c_str(), field(line, "vertices"), field(line, "holes"), field(line, "filled"),
              field(line, "minEdges"), field(line, "maxEdges"), field(line, "borderEdges"), newVertices, fill, inHoles,
              fill - inHoles, 1e6 * inHoles / std::max(newVertices, 1.0), 1e3 * field(line, "intercept"),
              1e6 * field(line, "slope"), mesh, extra, (mesh + extra) / mesh, (mesh + extra) / output, field(line, "openEdges"));
  return 0;
}

int main(int argc, char** argv) { return bench::guardedMain("scan_holes_bench", run, argc, argv); }
