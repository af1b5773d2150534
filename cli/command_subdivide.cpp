// SPDX-License-Identifier: GPL-3.0-or-later
// `elastica subdivide IN -o OUT.ply [--levels N]`: linear 1-to-4 subdivision (every triangle split
// at its edge midpoints; no vertex moves). The step of `fair --subdivide` on its own, for
// coarse-to-fine schedules a script drives stage by stage (bench/paper_figures.sh).
#include "commands.h"
#include "mesh_command.h"
#include "mesh_files.h"

#include <elastica/subdivision.h>

#include <cstdio>

namespace elastica::cli {
namespace {

struct SubdivideArgs {
  std::string input, output;
  int levels = 1;
  bool ascii = false;
};

void runSubdivide(const SubdivideArgs& a) {
  checkMeshOutput(a.output, a.input);
  TriMesh mesh = loadMesh(a.input).mesh;
  const int inVertices = mesh.vertexCount(), inFaces = mesh.faceCount();
  for (int l = 0; l < a.levels; ++l) subdivideMidpoint(mesh);
  writeMeshFile(a.output, mesh, {}, !a.ascii);
  std::printf("%s: %s, %s -> %s, %s\nwrote %s\n", a.input.c_str(), plural(inVertices, "vertex").c_str(),
              plural(inFaces, "face").c_str(), plural(mesh.vertexCount(), "vertex").c_str(),
              plural(mesh.faceCount(), "face").c_str(), a.output.c_str());
}

}  // namespace

void addSubdivideCommand(CLI::App& app) {
  auto args = std::make_shared<SubdivideArgs>();
  CLI::App* cmd = addMeshCommand(app, "subdivide", args->input, args->output,
                                 "Linear 1-to-4 subdivision: split every triangle at its edge midpoints (no vertex moves).");
  cmd->add_option("--levels", args->levels, "number of 1-to-4 subdivisions")->capture_default_str()->check(CLI::Range(1, 6));
  cmd->add_flag("--ascii", args->ascii, kAsciiHelp);
  cmd->callback([args] { runSubdivide(*args); });
}

}  // namespace elastica::cli
