// SPDX-License-Identifier: GPL-3.0-or-later
// `elastica curvature IN -o OUT.ply`: discrete mean and Gaussian curvature and the total
// curvature energy of a mesh.
#include "commands.h"
#include "flow_options.h"
#include "mesh_command.h"
#include "mesh_files.h"

#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/errors.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>

namespace elastica::cli {
namespace {

struct CurvatureArgs {
  std::string input, output;
  bool ascii = false;
  app::ParamValues given;  // the table's options given, by row
};

void runCurvature(const CurvatureArgs& a) {
  checkMeshOutput(a.output, a.input);
  const TriMesh mesh = loadMesh(a.input).mesh;
  // readMesh refused inconsistent orientation and non-manifold edges and split bow-tie vertices.
  const CurvatureMeasureOptions opt =
      app::readJob(app::filterSpec(app::FilterId::Curvature, {}), a.given, app::Caller::Cli).curvature;
  const app::CurvatureResult r = app::runCurvature(mesh, opt);
  const MeshCurvature& c = r.curvature;

  writeCurvatureMesh(a.output, mesh, r.outputH(), c.K, a.ascii, /*color=*/true);

  std::printf("%s: %s, %s, %s, Euler characteristic %d\n", a.input.c_str(), plural(mesh.vertexCount(), "vertex").c_str(),
              plural(mesh.faceCount(), "face").c_str(), c.boundaryEdges ? "with boundary" : "closed",
              c.eulerCharacteristic);
  for (const app::LogLine& line : r.log)
    std::printf("%s%s\n", line.severity == app::Severity::Warning ? "warning: " : "", line.text.c_str());
  std::printf("wrote %s\n", a.output.c_str());
}

}  // namespace

void addCurvatureCommand(CLI::App& app) {
  auto args = std::make_shared<CurvatureArgs>();
  CLI::App* cmd = addMeshCommand(app, "curvature", args->input, args->output,
      "Compute discrete mean curvature H, Gaussian curvature K and the total curvature energy\n"
      "E = sum (4H^2 - 2K) A_i. Writes per-vertex mean_curvature, gaussian_curvature,\n"
      "quality (= H, +1/r on a sphere with outward normals) and a colour ramp by H (in a .ply output).");
  addTableOptions(*cmd, app::FilterId::Curvature, args->given);
  cmd->add_flag("--ascii", args->ascii, kAsciiHelp);
  cmd->callback([args] { runCurvature(*args); });
}

}  // namespace elastica::cli
