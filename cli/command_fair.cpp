// SPDX-License-Identifier: GPL-3.0-or-later
// `elastica fair IN -o OUT`: fair a mesh with the discrete elastica flow (or a comparison flow),
// optionally coarse to fine, optionally only its selected faces.
#include "commands.h"
#include "face_index_file.h"
#include "flow_options.h"
#include "flow_report.h"
#include "mesh_command.h"
#include "mesh_files.h"

#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/app/reports.h>
#include <elastica/errors.h>

#include <elastica/face_set.h>

#include <cstdio>
#include <iostream>
#include <optional>

namespace elastica::cli {
namespace {

struct FairArgs {
  std::string input, output, report, selectedFaces;
  bool ascii = false, progress = false;
  app::ParamValues given;  // the table's options given, by row
};

void runFair(FairArgs& a) {
  checkMeshOutput(a.output, a.input);
  if (!a.report.empty()) io::checkOutputPath(a.report, a.input);
  io::MeshFile file = loadMesh(a.input);
  const io::ReadReport& read = file.report;
  TriMesh input = std::move(file.mesh);
  const int inVertices = input.vertexCount(), inFaces = input.faceCount();
  app::JobOptions job = app::readJob(app::filterSpec(app::FilterId::Fairing, {}), a.given, app::Caller::Cli);
  FlowOptions& flow = job.flow;

  std::optional<FaceSet> region;
  if (job.selected) {
    if (!read.hasFaceSelection) throw InvalidInputError(a.input + ": --selected, but the file has no face selection flags");
    region = FaceSet::fromFlags(file.faceSelection);
    if (region->faces.empty()) throw InvalidInputError(a.input + ": --selected, but no face is selected");
  }
  if (!a.selectedFaces.empty()) {
    // The indices count the file's faces; reading must not have renumbered them.
    const int changed = read.polygonsTriangulated + read.degenerateFacesRemoved + read.duplicateFacesRemoved;
    if (changed > 0)
      throw InvalidInputError(a.input + ": --selected-faces, but reading changed the file's faces (" +
                              std::to_string(read.polygonsTriangulated) + " polygons triangulated, " +
                              std::to_string(read.degenerateFacesRemoved + read.duplicateFacesRemoved) +
                              " faces removed), so its face numbers do not match; save the mesh as triangles first");
    region = FaceSet::fromFlags(readFaceIndexFile(a.selectedFaces, inFaces));
  }

  flow.progress = terminalProgress("fair", a.progress);
  app::FairingResult result;
  try {
    result = app::runFairing(std::move(input), std::move(region), flow, /*outputCurvature=*/true);
  } catch (const FlowDivergedError& e) {
    endProgressLine();
    // The mesh is not written, but the report tells how far the run got and why it stopped.
    if (!a.report.empty()) {
      nlohmann::json j = app::fairingReport(e.report(), flow, inVertices, inFaces);
      j["input"]["file"] = a.input;
      j["error"] = e.what();
      writeJson(a.report, j);
    }
    throw;
  } catch (const InvalidInputError& e) {  // e.g. nothing can move, a sliver: say which file
    endProgressLine();
    throw InvalidInputError(a.input + ": " + e.what());
  } catch (...) {
    endProgressLine();
    throw;
  }
  endProgressLine();

  // The file's other attributes are not written (the reader keeps only the face selection).
  const MeshCurvature& curv = result.curvature;
  writeCurvatureMesh(a.output, result.mesh, curv.H, curv.K, a.ascii, job.colorByMeanCurvature);
  const TriMesh& mesh = result.mesh;
  const FlowReport& report = result.report;

  std::printf("%s: %d vertices, %d faces -> %d vertices, %d faces\n", a.input.c_str(), inVertices, inFaces,
              mesh.vertexCount(), mesh.faceCount());
  std::printf("flow %s, scheme %s: %lld steps in %.2f s (%s), %zu stage%s\n", app::nameOf(flow.flow),
              app::nameOf(report.scheme), report.steps, report.seconds,
              app::nameOf(report.stop), report.stages.size(), report.stages.size() == 1 ? "" : "s");
  if (!report.refusedBecause.empty()) {
    if (report.keptStage < 0)
      std::printf("warning: the flow's last state was not kept (%s): the mesh is unchanged\n",
                  report.refusedBecause.c_str());
    else
      std::printf("warning: the flow's last state was not kept (%s): the mesh is the state at the end of stage %d of %zu\n",
                  report.refusedBecause.c_str(), report.keptStage + 1, report.stages.size());
  }
  if (!report.regionFaces.empty())
    std::printf("region energy %.9g -> %.9g (the selected faces' vertices, fixed rings included)\n",
                report.regionEnergyBefore, report.regionEnergyAfter);
  std::printf("mesh energy %.9g -> %.9g (the whole mesh)\n", result.meshEnergyBefore, result.meshEnergyAfter);
  if (!result.flowEnergyLine.empty()) std::printf("%s\n", result.flowEnergyLine.c_str());
  for (const std::string* line : {&result.resolutionLine, &result.amountLine, &result.roughLine, &result.movedLine})
    if (!line->empty()) std::printf("%s\n", line->c_str());
  std::printf("wrote %s\n", a.output.c_str());

  if (!a.report.empty())
    writeReport(a.report, app::fairingReport(report, flow, inVertices, inFaces, &result), a.input, a.output);
}

}  // namespace

void addFairCommand(CLI::App& app) {
  auto args = std::make_shared<FairArgs>();
  CLI::App* cmd = addMeshCommand(app, "fair", args->input, args->output,
      "Fair a mesh with the discrete elastica flow F = -Lap H - 2H(H^2-K) (or a comparison flow),\n"
      "optionally coarse to fine. Writes H as quality (and colour with --color-by-mean-curvature) in a .ply output.");
  addTableOptions(*cmd, app::FilterId::Fairing, args->given);
  addFlowChecks(*cmd, app::FilterId::Fairing, args->given);
  cmd->add_option("--selected-faces", args->selectedFaces,
                  "fair only the faces listed in this text file (0-based face indices, separated by spaces, commas or "
                  "lines; # starts a comment); two rings around stay fixed")
      ->excludes(cmd->get_option("--selected"));
  cmd->add_option("--report", args->report, "write a JSON report (energies, steps, stages, energy history)");
  addProgressFlag(*cmd, args->progress);
  cmd->add_flag("--ascii", args->ascii, kAsciiHelp);
  cmd->callback([args] { runFair(*args); });
}

}  // namespace elastica::cli
