// SPDX-License-Identifier: GPL-3.0-or-later
// `elastica generate SHAPE -o OUT.ply`: procedural meshes with known curvature (icosphere, torus,
// grid), for trying the tools and for held-out checks.
#include "commands.h"
#include "mesh_files.h"

#include <elastica/shapes.h>
#include <elastica/subdivision.h>

#include <cstdio>

namespace elastica::cli {
namespace {

struct GenerateArgs {
  std::string shape, output;
  double radius = 1, major = 3, minor = 1, spacing = 1, noise = 0;
  unsigned seed = 1;
  int level = -1;  // shape's default
  int window = 2;  // frame: cells per window side
  std::vector<int> segments;
  bool ascii = false;
};

void runGenerate(const GenerateArgs& a) {
  checkMeshOutput(a.output);
  auto seg = [&](int k, int def) { return static_cast<int>(a.segments.size()) > k ? a.segments[k] : def; };
  TriMesh mesh;
  if (a.shape == "icosphere") mesh = shapes::icosphere(a.radius, a.level < 0 ? 4 : a.level);
  else if (a.shape == "torus") mesh = shapes::torus(a.major, a.minor, seg(0, 64), seg(1, 32));
  else if (a.shape == "frame") {
    mesh = shapes::frameCage(seg(0, 2), seg(1, 1), a.window);
    for (int l = 0; l < (a.level < 0 ? 1 : a.level); ++l) subdivideMidpoint(mesh);
  }
  else mesh = shapes::grid(seg(0, 10), seg(1, 10), a.spacing);
  if (a.noise > 0) shapes::addRadialNoise(mesh, a.noise, a.seed);
  writeMeshFile(a.output, mesh, {}, !a.ascii);
  std::printf("wrote %s: %s, %d vertices, %d faces\n", a.output.c_str(), a.shape.c_str(), mesh.vertexCount(),
              mesh.faceCount());
}

}  // namespace

void addGenerateCommand(CLI::App& app) {
  auto args = std::make_shared<GenerateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "generate", "Write a procedural mesh: icosphere, torus, grid, or frame (the paper's coarse tubular cage).");
  cmd->add_option("shape", args->shape, "icosphere | torus | grid | frame")
      ->required()
      ->check(CLI::IsMember({"icosphere", "torus", "grid", "frame"}));
  cmd->add_option("-o,--output", args->output, kOutputHelp)->required();
  cmd->add_option("--radius", args->radius, "icosphere radius")->capture_default_str();
  cmd->add_option("--level", args->level,
                  "1-to-4 subdivisions: icosphere 10*4^level+2 vertices (default 4); frame (default 1)")
      ->check(CLI::Range(0, 8));
  cmd->add_option("--major", args->major, "torus: distance R of the tube's centre from the axis")
      ->capture_default_str();
  cmd->add_option("--minor", args->minor, "torus: tube radius r")->capture_default_str();
  cmd->add_option("--segments", args->segments, "torus: U,V segments (64,32); grid: X,Y cells (10,10); frame: X,Y windows (2,1)")
      ->delimiter(',')
      ->expected(1, 2);
  cmd->add_option("--spacing", args->spacing, "grid spacing")->capture_default_str();
  cmd->add_option("--window", args->window, "frame: side of each window in tube widths")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  cmd->add_option("--noise", args->noise,
                  "move each vertex radially from the origin by a random factor in [1-A, 1+A] (e.g. 0.05)")
      ->check(CLI::Range(0.0, 0.9));
  cmd->add_option("--seed", args->seed, "random seed for --noise")->capture_default_str();
  cmd->add_flag("--ascii", args->ascii, kAsciiHelp);
  cmd->callback([args] { runGenerate(*args); });
}

}  // namespace elastica::cli
