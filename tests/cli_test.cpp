// The `elastica` program end to end: generated and bundled real meshes, output files, exit codes.
#include "file_helpers.h"

#include <elastica/sign_convention.h>

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <regex>
#include <set>

namespace elastica {
using test::ScratchDir;

namespace {

struct CommandResult {
  int exitCode;
  std::string output;  // stdout and stderr together
};

CommandResult runElastica(const std::string& args) {
  const std::string cmd = std::string(ELASTICA_EXE) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), out};
}

double printedEnergy(const std::string& out) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex("total curvature energy E = ([-0-9.eE+]+)"))) return NAN;
  return std::stod(m[1]);
}

}  // namespace

// The held-out check of the foundation issue: a generated icosphere, then `curvature`; the
// written mean curvature is 1/r at every vertex to 0.5 %.
TEST(Cli, CurvatureOfGeneratedIcosphere) {
  ScratchDir dir("cli-sphere");
  const double r = 3.0;
  ASSERT_EQ(runElastica("generate icosphere --radius 3 --level 5 -o " + dir.file("s.ply")).exitCode, 0);
  const CommandResult run = runElastica("curvature " + dir.file("s.ply") + " -o " + dir.file("c.ply") + " --ascii");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NEAR(printedEnergy(run.output), 8 * M_PI, 0.01 * 8 * M_PI) << run.output;

  const test::AsciiPly ply = test::readAsciiPly(dir.file("c.ply"));
  ASSERT_EQ(ply.vertices.size(), 10242u);
  const int h = ply.column("mean_curvature"), k = ply.column("gaussian_curvature"), q = ply.column("quality");
  ASSERT_GE(h, 0);
  ASSERT_GE(k, 0);
  ASSERT_GE(q, 0);
  ASSERT_GE(ply.column("red"), 0);
  for (const auto& row : ply.vertices) {
    EXPECT_NEAR(row[h], 1 / r, 0.005 / r);
    EXPECT_NEAR(row[k], 1 / (r * r), 0.01 / (r * r));
    EXPECT_NEAR(row[q], row[h], 1e-5 * row[h]);  // quality carries H (ASCII keeps 6 digits)
  }
}

TEST(Cli, CurvatureOfBundledBunny) {
  ScratchDir dir("cli-bunny");
  const CommandResult run = runElastica("curvature " + std::string(ELASTICA_DATA_DIR) + "/bunny.ply -o " + dir.file("b.ply") + " --ascii");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("1839 vertices, 3674 faces, closed, Euler characteristic 2"), std::string::npos) << run.output;
  const double e = printedEnergy(run.output);
  // A closed genus-0 surface has E = 4W − 8π ≥ 8π (W ≥ 4π, Willmore); the bunny is far from round.
  EXPECT_GT(e, 8 * M_PI) << run.output;
  const test::AsciiPly ply = test::readAsciiPly(dir.file("b.ply"));
  EXPECT_EQ(ply.vertices.size(), 1839u);
  EXPECT_EQ(ply.faceCount, 3674);
  const int h = ply.column("mean_curvature"), red = ply.column("red"), blue = ply.column("blue");
  ASSERT_GE(h, 0);
  ASSERT_GE(red, 0);
  ASSERT_GE(blue, 0);
  // Colours follow a ramp (many distinct ones), and every value is finite.
  std::set<std::pair<int, int>> colours;
  for (const auto& row : ply.vertices) {
    EXPECT_TRUE(std::isfinite(row[h]));
    colours.emplace(int(row[red]), int(row[blue]));
  }
  EXPECT_GT(colours.size(), 100u);
}

TEST(Cli, BarycentricAndLambdaOptions) {
  ScratchDir dir("cli-opts");
  ASSERT_EQ(runElastica("generate icosphere --level 3 -o " + dir.file("s.ply")).exitCode, 0);
  const CommandResult bary = runElastica("curvature " + dir.file("s.ply") + " -o " + dir.file("b.ply") + " --area barycentric");
  ASSERT_EQ(bary.exitCode, 0) << bary.output;
  const CommandResult lambda = runElastica("curvature " + dir.file("s.ply") + " -o " + dir.file("l.ply") + " --lambda-fix");
  ASSERT_EQ(lambda.exitCode, 0) << lambda.output;
  EXPECT_NE(lambda.output.find("lambda = "), std::string::npos);
}

TEST(Cli, FailuresExitNonZeroAndWriteNothing) {
  ScratchDir dir("cli-fail");
  CommandResult run = runElastica("curvature " + dir.file("missing.ply") + " -o " + dir.file("out.ply"));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("no such file"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.ply")));

  test::writeText(dir.file("bad.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2\n");
  run = runElastica("curvature " + dir.file("bad.ply") + " -o " + dir.file("out.ply"));
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.ply")));

  // Non-manifold edge: three triangles on one edge.
  test::writeText(dir.file("nm.off"), "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  run = runElastica("curvature " + dir.file("nm.off") + " -o " + dir.file("out.ply"));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("non-manifold edge"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.ply")));

  ASSERT_EQ(runElastica("generate grid -o " + dir.file("g.ply")).exitCode, 0);
  run = runElastica("curvature " + dir.file("g.ply") + " -o " + dir.file("g.ply"));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("overwrite the input"), std::string::npos) << run.output;

  run = runElastica("curvature " + dir.file("g.ply") + " -o " + dir.file("no/such/dir/out.ply"));
  EXPECT_EQ(run.exitCode, 1);

  EXPECT_EQ(runElastica("curvature " + dir.file("g.ply")).exitCode, 2);  // -o missing
  EXPECT_EQ(runElastica("curvature " + dir.file("g.ply") + " -o x.ply --area voronoi").exitCode, 2);
  EXPECT_EQ(runElastica("frobnicate").exitCode, 2);
}

TEST(Cli, HelpForProgramAndSubcommands) {
  CommandResult run = runElastica("--help");
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_NE(run.output.find("curvature"), std::string::npos);
  run = runElastica("curvature --help");
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_NE(run.output.find("--lambda-fix"), std::string::npos);
  EXPECT_NE(run.output.find("--area"), std::string::npos);
  EXPECT_EQ(runElastica("generate --help").exitCode, 0);
}

}  // namespace elastica
