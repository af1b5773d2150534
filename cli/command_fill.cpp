// SPDX-License-Identifier: GPL-3.0-or-later
// `elastica fill IN -o OUT`: restore the missing regions of a mesh (paper §4): every hole up to a
// size is triangulated, refined to the surrounding density, started from a bi-Laplace solve and
// faired with the elastica flow while two rings around it stay fixed.
#include "commands.h"
#include "flow_options.h"
#include "flow_report.h"
#include "mesh_command.h"
#include "mesh_files.h"

#include <elastica/app/choices.h>
#include <elastica/app/filter_apply.h>
#include <elastica/app/reports.h>
#include <elastica/errors.h>
#include <elastica/hole_filling.h>
#include <elastica/vcg_mesh.h>

#include <cstdio>
#include <iostream>

namespace elastica::cli {
namespace {

struct FillArgs {
  std::string input, output, report;
  bool ascii = false, progress = false;
  app::ParamValues given;  // the table's options given, by row
};

// Room reserved for new vertices and faces, as a fraction of the input's (address space only until
// the patches use it; a fill that adds more grows the arrays by copying, as without it).
constexpr double kFillSpare = 0.5;

void runFill(FillArgs& a) {
  checkMeshOutput(a.output, a.input);
  app::JobOptions job = app::readJob(app::filterSpec(app::FilterId::FillHoles, {}), a.given, app::Caller::Cli);
  HoleFillOptions& fill = job.fill;
  if (!a.report.empty()) io::checkOutputPath(a.report, a.input);
  // The patches are appended to the mesh as read: with room for them reserved, its vertex and face
  // arrays grow in place. Without it, the face array (about 600 MB for a 2.2-million-vertex scan)
  // was copied into a larger one while both were held, the command's peak.
  VcgMesh vm;
  loadMesh(a.input, vm, kFillSpare);
  TriMesh input = toTriMesh(vm);
  const int inVertices = input.vertexCount(), inFaces = input.faceCount();

  fill.flow.progress = terminalProgress("fill", a.progress);
  app::FillHolesResult result;
  try {
    result = app::runFillHoles(std::move(input), fill, /*outputCurvature=*/true);
  } catch (...) {
    endProgressLine();
    throw;
  }
  endProgressLine();

  // New elements are appended: the input's own keep every attribute the file gave them. The new
  // faces are selected and flagged by a face property.
  app::writeBack(result, vm, /*selectNew=*/true);
  const HoleFillReport& report = result.report;
  auto isNewAttr = vcg::tri::Allocator<VcgMesh>::GetPerFaceAttribute<float>(vm, "elastica_new");
  for (std::size_t f = 0; f < vm.face.size(); ++f) isNewAttr[f] = report.isNewFace(static_cast<int>(f)) ? 1.0f : 0.0f;
  storeCurvature(vm, result.curvature.H, result.curvature.K);
  const int outVertices = result.mesh.vertexCount(), outFaces = result.mesh.faceCount();
  nlohmann::json json;
  if (!a.report.empty()) json = app::fillingReport(result, fill);
  // From here the vcglib mesh holds all that is written: the fill's own copy of the mesh and its
  // curvature go before the writer makes its arrays (about 150 MB for a 2.2-million-vertex scan).
  result.mesh = TriMesh();
  std::vector<double>().swap(result.curvature.H);
  std::vector<double>().swap(result.curvature.K);
  io::PlyWriteOptions w;
  w.binary = !a.ascii;
  w.vertexQuality = w.curvature = true;
  w.vertexColor = job.colorByMeanCurvature;
  w.faceFlags = true;
  w.faceFloatAttributes = {"elastica_new"};
  writeMeshFile(a.output, vm, w);

  int skipped = 0;
  for (std::size_t i = 0; i < report.holes.size(); ++i) {
    const HoleReport& h = report.holes[i];
    if (!h.filled) {
      ++skipped;
      std::printf("hole %zu: %d border edges, skipped: %s\n", i + 1, h.borderEdges, h.reason.c_str());
      continue;
    }
    std::printf("hole %zu: %d border edges, filled with %s and %s", i + 1, h.borderEdges,
                plural(h.newVertices, "vertex").c_str(), plural(h.newFaces, "face").c_str());
    if (h.steps > 0) std::printf(", energy %.6g -> %.6g in %lld steps (%s)", h.energyBefore, h.energyAfter, h.steps, app::nameOf(h.stop));
    std::printf(", smallest angle %.1f deg", h.minAngleDegrees);
    if (h.borderBoundDegrees < 25) std::printf(" (the border allows %.1f deg)", h.borderBoundDegrees);
    std::printf(", %.2f s\n", h.seconds);
    std::string stages;
    for (const FillStageReport& s : h.stages)
      if (s.stage != "triangulation") stages += (stages.empty() ? "" : ", ") + s.stage + (s.kept ? " kept" : " undone (" + s.why + ")");
    if (!stages.empty()) std::printf("  stages: %s\n", stages.c_str());
    if (!h.reason.empty()) std::cerr << "warning: hole " << i + 1 << ": " << h.reason << "\n";
  }
  if (!report.welds.empty())
    std::printf("merged %zu vertex %s into the vertex %s copied: two fans of faces met at one point and a patch "
                "joined them\n",
                report.welds.size(), report.welds.size() == 1 ? "copy" : "copies", report.welds.size() == 1 ? "it" : "they");
  std::printf("%s: %d vertices, %d faces -> %d vertices, %d faces; %s filled, %d skipped, %.2f s\n", a.input.c_str(),
              inVertices, inFaces, outVertices, outFaces, plural(report.filledCount(), "hole").c_str(),
              skipped, report.seconds);
  if (report.holes.empty())
    std::printf("the mesh has no holes: nothing to fill; wrote %s with the input's vertices and faces unchanged\n", a.output.c_str());
  else if (io::formatFromExtension(a.output) == io::MeshFormat::Ply)
    std::printf("wrote %s (new faces selected and flagged by the face property elastica_new)\n", a.output.c_str());
  else
    std::printf("wrote %s\n", a.output.c_str());

  if (!a.report.empty()) writeReport(a.report, std::move(json), a.input, a.output);
}

}  // namespace

void addFillCommand(CLI::App& app) {
  auto args = std::make_shared<FillArgs>();
  CLI::App* cmd = addMeshCommand(app, "fill", args->input, args->output,
      "Fill the holes of a mesh with patches that continue its curvature (the paper's restoration):\n"
      "minimum-weight triangulation, refinement to the surrounding density, a bi-Laplace start, then\n"
      "the elastica flow (semi-implicit by default) with two rings around each hole fixed.\n"
      "Original vertices and faces are kept bit for bit; new faces are selected in the output. (A hole\n"
      "border that passes twice through one point, as two copies of a vertex, is split there and the\n"
      "copies merged where a patch joins their fans.)");
  addTableOptions(*cmd, app::FilterId::FillHoles, args->given);
  addFlowChecks(*cmd, app::FilterId::FillHoles, args->given);
  cmd->add_option("--report", args->report, "write a JSON report (one entry per hole)");
  addProgressFlag(*cmd, args->progress);
  cmd->add_flag("--ascii", args->ascii, kAsciiHelp);
  cmd->callback([args] { runFill(*args); });
}

}  // namespace elastica::cli
