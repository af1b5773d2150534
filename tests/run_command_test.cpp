// SPDX-License-Identifier: GPL-3.0-or-later
// `elastica run -i IN -o OUT -s SCRIPT.mlx`: script handling (defaults with warnings, clear errors
// for unknown filters, parameters and values) and its results. The agreement with meshlabserver
// and the plugin is tested in tests/plugin/.
#include "run_elastica.h"
#include "file_helpers.h"

#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/shapes.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <gtest/gtest.h>

#include <filesystem>

namespace elastica {
namespace {

using test::CommandResult;
using test::ScratchDir;

const std::string kScripts = ELASTICA_PLUGIN_SCRIPTS_DIR;

using test::runElastica;

std::string script(const std::string& filters) {
  return "<!DOCTYPE FilterScript>\n<FilterScript>\n" + filters + "</FilterScript>\n";
}

const char* kCurvatureFilter =
    " <filter name=\"Discrete Elastica Curvature\">\n"
    "  <Param type=\"RichBool\" name=\"lambdaFix\" value=\"false\"/>\n"
    "  <Param type=\"RichEnum\" name=\"area\" value=\"0\" enum_cardinality=\"2\"/>\n"
    " </filter>\n";

class RunCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    TriMesh sphere = shapes::icosphere(2.0, 2);
    shapes::addRadialNoise(sphere, 0.05, 5);
    VcgMesh vm;
    fromTriMesh(sphere, vm);
    io::writePly(input, vm, {});
  }
  CommandResult runScript(const std::string& text) {
    test::writeText(mlx, text);
    return runElastica("run -i " + input + " -o " + output + " -s " + mlx + " --ascii");
  }

  ScratchDir dir{"run-command"};
  std::string input = dir.file("noisy.ply"), output = dir.file("out.ply"), mlx = dir.file("s.mlx");
};

TEST_F(RunCommand, CurvatureScriptWritesQualityAndAttributes) {
  const CommandResult r = runScript(script(kCurvatureFilter));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("Discrete Elastica Curvature: total curvature energy E = "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  const test::AsciiPly ply = test::readAsciiPly(output);
  for (const char* column : {"quality", "red", "mean_curvature", "gaussian_curvature"})
    EXPECT_GE(ply.column(column), 0) << column;
  // H = +1/r on the (noisy) sphere of radius 2, on average.
  double sum = 0;
  for (const auto& row : ply.vertices) sum += row[ply.column("mean_curvature")];
  EXPECT_NEAR(sum / double(ply.vertices.size()), 0.5, 0.05);
}

// Missing parameters take their defaults, each with a warning naming it.
TEST_F(RunCommand, MissingParametersWarnAndTakeDefaults) {
  const CommandResult r = runElastica("run -i " + input + " -o " + output + " -s " + kScripts +
                                      "/fairing_missing_parameters.mlx");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* name : {"flow", "scheme", "maxSeconds", "featureSize", "subdivisionLevels", "energyTolerance", "tangentialDrift", "boundary",
                           "Selected", "colorByMeanCurvature"})
    EXPECT_NE(r.output.find("does not set '" + std::string(name) + "'; using its default"), std::string::npos) << name;
  EXPECT_EQ(r.output.find("does not set 'maxSteps'"), std::string::npos) << r.output;
  // featureSize took the mesh's amount, as MeshLab's dialog shows it: its four steps end the run
  // before the script's maxSteps (5) does.
  EXPECT_NE(r.output.find(" 4 steps"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(faired to the feature size)"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(output));
}

// Every shipped script lists every parameter of its filters (Debian's meshlabserver aborts on a
// script that leaves one out, and `elastica run` would warn): maxSeconds included.
TEST_F(RunCommand, ShippedScriptsListEveryParameter) {
  const std::filesystem::path examples = std::filesystem::path(kScripts) / "../../../meshlab_plugin/examples";
  int checked = 0;
  for (const auto& dir : {std::filesystem::path(kScripts), examples})
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (entry.path().extension() != ".mlx" || name == "fairing_missing_parameters.mlx" ||
          name == "unknown_filter.mlx")
        continue;
      // The warnings come before any filter runs; the tiny sphere keeps the runs short.
      const CommandResult r = runElastica("run -i " + input + " -o " + output + " -s " + entry.path().string());
      EXPECT_EQ(r.output.find("does not set"), std::string::npos) << name << "\n" << r.output;
      ++checked;
    }
  EXPECT_GE(checked, 5);
}

// An unknown filter is an error naming it, before any work: nothing is written.
TEST_F(RunCommand, UnknownFilterIsAnErrorNamingIt) {
  const CommandResult r = runElastica("run -i " + input + " -o " + output + " -s " + kScripts + "/unknown_filter.mlx");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("unknown filter 'Laplacian Smooth'"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("total curvature energy"), std::string::npos) << r.output;  // nothing ran
  EXPECT_FALSE(std::filesystem::exists(output));
}

TEST_F(RunCommand, BadParametersAreErrors) {
  const std::string fairing = "<filter name=\"Discrete Elastica Fairing\">";
  const std::vector<std::pair<std::string, std::string>> cases{
      {fairing + "<Param type=\"RichInt\" name=\"steps\" value=\"3\"/></filter>", "'steps' is not one of its parameters"},
      {fairing + "<Param type=\"RichFloat\" name=\"maxSteps\" value=\"3\"/></filter>", "is a RichInt, not a RichFloat"},
      {fairing + "<Param type=\"RichInt\" name=\"maxSteps\" value=\"many\"/></filter>", "'many' is not a RichInt value"},
      {fairing + "<Param type=\"RichBool\" name=\"Selected\" value=\"yes\"/></filter>", "'yes' is not a RichBool value"},
      {fairing + "<Param type=\"RichInt\" name=\"maxSteps\" value=\"3\"/><Param type=\"RichInt\" name=\"maxSteps\" "
                 "value=\"4\"/></filter>",
       "is given twice"},
      {fairing + "<Param type=\"RichEnum\" name=\"flow\" value=\"7\"/></filter>", "enum value 7 is not in 0..2"},
      {fairing + "<Param type=\"RichInt\" name=\"subdivisionLevels\" value=\"-1\"/></filter>",
       "'Subdivision levels' (subdivisionLevels) must be in 0..8"},
      {"<filter name=\"Fill Holes with Discrete Elastica\"><Param type=\"RichInt\" name=\"MaxHoleSize\" value=\"2\"/>"
       "</filter>",
       "'Max size to be closed' (MaxHoleSize) must be >= 3 (a hole has 3 edges or more)"},
      {fairing + "<Param type=\"RichFloat\" name=\"maxSeconds\" value=\"-1\"/></filter>",
       "'Time limit (s)' (maxSeconds) must be >= 0"},
      {"<filter name=\"Discrete Elastica Curvature\"><Param type=\"RichBool\" name=\"lambdaFix\"/></filter>",
       "has no value attribute"},
  };
  for (const auto& [filter, message] : cases) {
    const CommandResult r = runScript(script(filter));
    EXPECT_EQ(r.exitCode, 1) << filter << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << filter << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << filter;
  }
  const CommandResult notXml = runScript("<FilterScript><filter name=\"x\">");
  EXPECT_EQ(notXml.exitCode, 1);
  EXPECT_NE(notXml.output.find("not well-formed XML"), std::string::npos) << notXml.output;
  const CommandResult wrongRoot = runScript("<Script/>");
  EXPECT_NE(wrongRoot.output.find("root element must be <FilterScript>"), std::string::npos) << wrongRoot.output;
}

// Filters run in order on the same mesh: fairing a noisy sphere, then its curvature is near 1/r.
TEST_F(RunCommand, FiltersRunInOrder) {
  const std::string fair =
      " <filter name=\"Discrete Elastica Fairing\">\n"
      "  <Param type=\"RichEnum\" name=\"scheme\" value=\"1\"/>\n"
      "  <Param type=\"RichAbsPerc\" name=\"featureSize\" value=\"0\"/>\n"
      " </filter>\n";
  const CommandResult r = runScript(script(std::string(fair) + kCurvatureFilter));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_LT(r.output.find("Discrete Elastica Fairing:"), r.output.find("Discrete Elastica Curvature:")) << r.output;
  const test::AsciiPly ply = test::readAsciiPly(output);
  double lo = 1e9, hi = -1e9;
  for (const auto& row : ply.vertices) {
    lo = std::min(lo, row[ply.column("mean_curvature")]);
    hi = std::max(hi, row[ply.column("mean_curvature")]);
  }
  EXPECT_GT(lo, 0.45);
  EXPECT_LT(hi, 0.55);
}

}  // namespace
}  // namespace elastica
