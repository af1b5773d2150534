// `elastica curvature IN -o OUT.ply`: discrete mean and Gaussian curvature and the total
// curvature energy of a mesh.
#include "commands.h"
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
  VertexArea area = VertexArea::Mixed;
  bool lambdaFix = false;
};

void runCurvature(const CurvatureArgs& a) {
  checkMeshOutput(a.output, a.input);
  const TriMesh mesh = loadMesh(a.input).mesh;
  // readMesh refused inconsistent orientation and non-manifold edges and split bow-tie vertices.
  CurvatureMeasureOptions opt;
  opt.area = a.area;
  opt.curvature.h2k = a.lambdaFix ? H2KTreatment::PaperLambda : H2KTreatment::Clamp;
  const app::CurvatureResult r = app::runCurvature(mesh, opt);
  const MeshCurvature& c = r.curvature;

  writeCurvatureMesh(a.output, mesh, r.outputH(), c.K, a.ascii, /*color=*/true);

  std::printf("%s: %s, %s, %s, Euler characteristic %d\n", a.input.c_str(), plural(mesh.vertexCount(), "vertex").c_str(),
              plural(mesh.faceCount(), "face").c_str(), c.boundaryEdges ? "with boundary" : "closed",
              c.eulerCharacteristic);
  for (const std::string& line : r.log) std::printf("%s\n", line.c_str());
  std::printf("wrote %s\n", a.output.c_str());
}

}  // namespace

void addCurvatureCommand(CLI::App& app) {
  auto args = std::make_shared<CurvatureArgs>();
  CLI::App* cmd = app.add_subcommand(
      "curvature",
      "Compute discrete mean curvature H, Gaussian curvature K and the total curvature energy\n"
      "E = sum (4H^2 - 2K) A_i. Writes per-vertex mean_curvature, gaussian_curvature,\n"
      "quality (= H, +1/r on a sphere with outward normals) and a colour ramp by H (in a .ply output).");
  cmd->add_option("input", args->input, "input mesh (.ply, .off, .stl, .obj)")->required();
  cmd->add_option("-o,--output", args->output, kOutputHelp)->required();
  cmd->add_flag("--ascii", args->ascii, kAsciiHelp);
  cmd->add_option("--area", args->area,
                  "vertex area: mixed (Meyer et al.'s mixed Voronoi area, default) or barycentric (the paper's A/3)")
      ->transform(CLI::CheckedTransformer(app::nameMap<VertexArea>(), CLI::ignore_case));
  cmd->add_flag("--lambda-fix", args->lambdaFix,
                "apply the paper's lambda rescaling of H where H^2 < K (guarded); E still uses raw H");
  cmd->callback([args] { runCurvature(*args); });
}

}  // namespace elastica::cli
