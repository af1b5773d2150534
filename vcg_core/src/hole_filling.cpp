#include <elastica/biharmonic_embedding.h>
#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/hole_boundary.h>
#include <elastica/hole_filling.h>
#include <elastica/hole_triangulation.h>
#include <elastica/mesh_quality.h>
#include <elastica/submesh.h>
#include <elastica/tangential_relaxation.h>
#include <elastica/topology.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace elastica {
namespace {

// Face-rings around the patch handed to the flow: the patch's border vertices need complete fans
// (H is evaluated there) and their neighbours are the second fixed ring; one more ring of margin.
constexpr int kFlowRings = 3;

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// Mean length of the mesh edges at each loop vertex: the density the patch must match.
std::vector<double> borderEdgeLengths(const TriMesh& mesh, const Topology& topo, const HoleLoop& loop) {
  std::vector<double> sigma;
  for (int v : loop.vertices) {
    double sum = 0;
    for (int k = topo.ringBegin(v); k < topo.ringEnd(v); ++k) sum += (mesh.positions[topo.ringVertex(k)] - mesh.positions[v]).norm();
    sigma.push_back(sum / std::max(topo.valence(v), 1));
  }
  return sigma;
}

// Refines, embeds and fairs the patch (the faces flagged in `patchFace`) of `sub`, a piece of the
// mesh around one hole. The vertices from `firstNew` on are the patch's own; nothing else moves.
// The flow's step and time limits hold for the whole fill: each hole's flow gets what the work
// before it left (a limit already used up stops the flow at once; it keeps the bi-Laplace patch).
FlowOptions remainingFlowBudget(const FlowOptions& flow, long long stepsUsed, double secondsUsed) {
  FlowOptions f = flow;
  f.maxSteps = std::max<long long>(flow.maxSteps - stepsUsed, 0);
  if (flow.maxSeconds > 0) f.maxSeconds = std::max(flow.maxSeconds - secondsUsed, 1e-9);  // 0 would mean none
  return f;
}

void restorePatch(TriMesh& sub, std::vector<std::uint8_t>& patchFace, std::vector<double>& sigma, int firstNew,
                  const HoleFillOptions& opt, const FlowOptions& flowBudget, HoleReport& hole) {
  refinePatch(sub, patchFace, sigma, opt.refinement);
  if (opt.stopAfter == FillStage::Refinement || sub.vertexCount() == firstNew) return;
  auto freeVertices = [&] {
    std::vector<std::uint8_t> free(sub.positions.size(), 0);
    std::fill(free.begin() + firstNew, free.end(), 1);
    return free;
  };
  try {
    solveBiharmonic(sub, freeVertices());
    // The embedded patch is larger than the flat fill where the hole is deep: refine where it
    // stretched, and solve again.
    const int before = sub.vertexCount();
    refinePatch(sub, patchFace, sigma, opt.refinement);
    if (sub.vertexCount() > before) solveBiharmonic(sub, freeVertices());
  } catch (const NumericalError& e) {
    hole.reason = std::string(e.what()) + "; kept the flat patch";
    return;
  }
  if (opt.stopAfter == FillStage::Biharmonic) return;

  const std::vector<std::uint8_t> free = freeVertices();
  relaxTangentially(sub, free);
  FlowOptions flow = flowBudget;
  flow.boundary = BoundaryMode::Fixed;
  const TriMesh start = sub;
  try {
    const FlowReport r = fair(sub, &patchFace, flow);
    hole.energyBefore = r.energyInitial;
    hole.energyAfter = r.energyFinal;
    hole.steps = r.steps;
    hole.stop = r.stop;
  } catch (const FlowDivergedError& e) {
    sub = start;
    hole.energyBefore = hole.energyAfter = e.report().energyInitial;
    hole.steps = e.report().steps;
    hole.stop = StopReason::Diverged;
    hole.reason = std::string(e.what()) + "; kept the bi-Laplace patch";
  } catch (const Error& e) {  // e.g. a sliver that makes the explicit step vanish
    sub = start;
    hole.reason = std::string(e.what()) + "; kept the bi-Laplace patch";
  }
}

void validate(const HoleFillOptions& opt) {
  if (opt.maxHoleEdges < 3) throw InvalidInputError("fill: the largest hole to fill must have at least 3 border edges");
  if (!(opt.refinement.density > 0)) throw InvalidInputError("fill: the refinement density must be > 0");
  if (opt.flow.subdivisionLevels != 0)
    throw InvalidInputError("fill: subdivision is not available when filling holes (it would split the original faces)");
}

}  // namespace

int HoleFillReport::filledCount() const {
  return static_cast<int>(std::count_if(holes.begin(), holes.end(), [](const HoleReport& h) { return h.filled; }));
}

HoleFillReport fillHoles(TriMesh& output, std::vector<std::uint8_t>* newFaceFlags, const HoleFillOptions& opt) {
  validate(opt);
  TriMesh mesh = output;  // the input stays as it was if anything throws
  const auto start = std::chrono::steady_clock::now();
  const Topology topo(mesh.vertexCount(), mesh.faces);  // throws on non-manifold edges
  const int originalFaces = mesh.faceCount();
  VertexFaces adjacency = vertexFaces(mesh);
  auto edgeExists = [&](int a, int b) {
    for (int f : adjacency[a]) {
      const Face& t = mesh.faces[f];
      if (t[0] == b || t[1] == b || t[2] == b) return true;
    }
    return false;
  };

  HoleFillReport report;
  long long flowSteps = 0;  // over all holes, against opt.flow.maxSteps
  for (const HoleLoop& loop : findHoleLoops(topo)) {
    const auto holeStart = std::chrono::steady_clock::now();
    HoleReport hole;
    hole.borderEdges = loop.edgeCount();
    auto skip = [&](std::string why) {
      hole.reason = std::move(why);
      hole.seconds = seconds(holeStart);
      report.holes.push_back(hole);
    };
    if (loop.edgeCount() > opt.maxHoleEdges) {
      skip("larger than the limit of " + std::to_string(opt.maxHoleEdges) + " border edges");
      continue;
    }
    if (loop.pinched) {
      skip("its border touches itself at a vertex");
      continue;
    }
    const auto triangles = triangulateHole(mesh.positions, loop, edgeExists);
    if (!triangles) {
      skip("no triangulation avoids the mesh's existing edges");
      continue;
    }
    const int firstVertex = mesh.vertexCount(), firstFace = mesh.faceCount();
    for (const Face& t : *triangles) {
      mesh.faces.push_back(t);
      for (int v : t) adjacency[v].push_back(mesh.faceCount() - 1);
    }
    hole.filled = true;
    if (opt.stopAfter != FillStage::Triangulation) {
      // Work on the piece of the mesh around the hole, then write the patch back.
      Submesh sub = extractSubmesh(mesh, adjacency, loop.vertices, kFlowRings);
      const int subVertices = sub.mesh.vertexCount(), subFaces = sub.mesh.faceCount();
      std::vector<std::uint8_t> patchFace(subFaces, 0);
      for (int f = 0; f < subFaces; ++f) patchFace[f] = sub.face[f] >= firstFace;
      std::vector<double> sigma(subVertices, 0);
      const std::vector<double> borderSigma = borderEdgeLengths(mesh, topo, loop);
      for (int i = 0; i < subVertices; ++i) {
        const auto at = std::find(loop.vertices.begin(), loop.vertices.end(), sub.vertex[i]);
        if (at != loop.vertices.end()) sigma[i] = borderSigma[at - loop.vertices.begin()];
      }
      restorePatch(sub.mesh, patchFace, sigma, subVertices, opt, remainingFlowBudget(opt.flow, flowSteps, seconds(start)),
                   hole);
      flowSteps += hole.steps;

      auto global = [&](int i) { return i < subVertices ? sub.vertex[i] : firstVertex + i - subVertices; };
      for (int i = subVertices; i < sub.mesh.vertexCount(); ++i) mesh.positions.push_back(sub.mesh.positions[i]);
      adjacency.resize(mesh.positions.size());
      for (int f = 0; f < sub.mesh.faceCount(); ++f) {
        if (!patchFace[f]) continue;
        const Face& t = sub.mesh.faces[f];
        const Face g{global(t[0]), global(t[1]), global(t[2])};
        if (f < subFaces) mesh.faces[sub.face[f]] = g;
        else mesh.faces.push_back(g);
      }
      // The patch was rewired: renew the face lists of its border.
      for (int v : loop.vertices) {
        auto& faces = adjacency[v];
        faces.erase(std::remove_if(faces.begin(), faces.end(), [&](int f) { return f >= firstFace; }), faces.end());
      }
      for (int f = firstFace; f < mesh.faceCount(); ++f) {
        for (int v : mesh.faces[f]) adjacency[v].push_back(f);
      }
    }
    hole.newVertices = mesh.vertexCount() - firstVertex;
    hole.newFaces = mesh.faceCount() - firstFace;
    hole.minAngleDegrees = smallestAngleDegrees(mesh, firstFace);
    hole.seconds = seconds(holeStart);
    report.holes.push_back(hole);
    if (hole.stop == StopReason::Cancelled) break;  // the caller's progress callback said stop
  }
  if (newFaceFlags) {
    newFaceFlags->assign(mesh.faces.size(), 0);
    std::fill(newFaceFlags->begin() + originalFaces, newFaceFlags->end(), 1);
  }
  output = std::move(mesh);
  report.seconds = seconds(start);
  return report;
}

}  // namespace elastica
