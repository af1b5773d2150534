// `elastica fair IN -o OUT`: fair a mesh with the discrete elastica flow (or a comparison flow),
// optionally coarse to fine, optionally only its selected faces.
#include "commands.h"
#include "face_index_file.h"
#include "flow_options.h"
#include "flow_report.h"
#include "mesh_files.h"

#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/app/reports.h>
#include <elastica/errors.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace elastica::cli {
namespace {

struct FairArgs {
  std::string input, output, report, selectedFaces;
  bool ascii = false, color = false, progress = false, selected = false;
  double featureSize = 0;  // a fraction of the bounding-box diagonal
  FlowOptions flow;
};

void runFair(FairArgs& a) {
  checkMeshOutput(a.output, a.input);
  if (!a.report.empty()) io::checkOutputPath(a.report, a.input);
  io::MeshFile file = loadMesh(a.input);
  const io::ReadReport& read = file.report;
  TriMesh input = std::move(file.mesh);
  const int inVertices = input.vertexCount(), inFaces = input.faceCount();

  std::vector<std::uint8_t> selection;
  if (a.selected) {
    if (!read.hasFaceSelection) throw InvalidInputError(a.input + ": --selected, but the file has no face selection flags");
    selection = std::move(file.faceSelection);
    if (std::count(selection.begin(), selection.end(), 1) == 0)
      throw InvalidInputError(a.input + ": --selected, but no face is selected");
  }
  if (!a.selectedFaces.empty()) {
    // The indices count the file's faces; reading must not have renumbered them.
    const int changed = read.polygonsTriangulated + read.degenerateFacesRemoved + read.duplicateFacesRemoved;
    if (changed > 0)
      throw InvalidInputError(a.input + ": --selected-faces, but reading changed the file's faces (" +
                              std::to_string(read.polygonsTriangulated) + " polygons triangulated, " +
                              std::to_string(read.degenerateFacesRemoved + read.duplicateFacesRemoved) +
                              " faces removed), so its face numbers do not match; save the mesh as triangles first");
    selection = readFaceIndexFile(a.selectedFaces, inFaces);
  }

  a.flow.featureSize = a.featureSize * boundingBoxDiagonal(input.positions);
  a.flow.progress = terminalProgress("fair", a.progress);
  app::FairingResult result;
  try {
    result = app::runFairing(std::move(input), std::move(selection), a.flow, /*outputCurvature=*/true);
  } catch (const FlowDivergedError& e) {
    endProgressLine();
    // The mesh is not written, but the report tells how far the run got and why it stopped.
    if (!a.report.empty()) {
      nlohmann::json j = app::fairingReport(e.report(), a.flow, inVertices, inFaces);
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
  writeCurvatureMesh(a.output, result.mesh, curv.H, curv.K, a.ascii, a.color);
  const TriMesh& mesh = result.mesh;
  const FlowReport& report = result.report;

  std::printf("%s: %d vertices, %d faces -> %d vertices, %d faces\n", a.input.c_str(), inVertices, inFaces,
              mesh.vertexCount(), mesh.faceCount());
  std::printf("flow %s, scheme %s: %lld steps in %.2f s (%s), %zu stage%s\n", app::nameOf(a.flow.flow),
              app::nameOf(report.scheme), report.steps, report.seconds,
              app::nameOf(report.stop), report.stages.size(), report.stages.size() == 1 ? "" : "s");
  std::printf("energy %.9g -> %.9g\n", result.energyInput, result.energyOutput);
  for (const std::string& line : result.log)  // the flow's own start, when it differs from the input's
    if (line.rfind("the flow's energy", 0) == 0) std::printf("%s\n", line.c_str());
  std::printf("wrote %s\n", a.output.c_str());

  if (!a.report.empty()) {
    nlohmann::json j = app::fairingReport(report, a.flow, inVertices, inFaces, &result);
    j["input"]["file"] = a.input;
    j["output"]["file"] = a.output;
    writeJson(a.report, j);
    std::printf("wrote %s\n", a.report.c_str());
  }
}

}  // namespace

void addFairCommand(CLI::App& app) {
  auto args = std::make_shared<FairArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fair",
      "Fair a mesh with the discrete elastica flow F = -Lap H - 2H(H^2-K) (or a comparison flow),\n"
      "optionally coarse to fine. Writes H as quality (and colour with --color-by-mean-curvature) in a .ply output.");
  cmd->add_option("input", args->input, "input mesh (.ply, .off, .stl, .obj)")->required();
  cmd->add_option("-o,--output", args->output, kOutputHelp)->required();
  addFlowOptions(*cmd, args->flow);
  addWholeMeshFlowOptions(*cmd, args->flow);
  cmd->add_option("--feature-size", args->featureSize,
                  "a fairing amount: smooth away bumps smaller than this fraction of the bounding-box diagonal "
                  "(e.g. 0.03), keep larger shapes, then stop (default 0: fair until converged)")
      ->check(CLI::Range(0.0, 1.0));
  CLI::Option* selected = cmd->add_flag(
      "--selected", args->selected,
      "fair only the selected faces (PLY face flags, as MeshLab saves its selection, or a face property 'selected'); "
      "two rings around stay fixed");
  cmd->add_option("--selected-faces", args->selectedFaces,
                  "fair only the faces listed in this text file (0-based face indices, separated by spaces, commas or "
                  "lines; # starts a comment); two rings around stay fixed")
      ->excludes(selected);
  cmd->add_option("--report", args->report, "write a JSON report (energies, steps, stages, energy history)");
  addProgressFlag(*cmd, args->progress);
  cmd->add_flag("--ascii", args->ascii, kAsciiHelp);
  cmd->add_flag("--color-by-mean-curvature", args->color, "colour vertices by H (red low, blue high)");
  cmd->callback([args] { runFair(*args); });
}

}  // namespace elastica::cli
