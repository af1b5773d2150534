// SPDX-License-Identifier: GPL-3.0-or-later
// Debian's real meshlabserver loads the freshly built plugin from a private prefix under the build
// directory (nothing is installed into /usr) and runs .mlx scripts of each filter; its output must
// match `elastica run` with the same script and input: same counts, positions within 1e-5 of the
// bounding-box diagonal (MeshLab stores float; both compute in double on a copy). Runs under
// `scripts/with-xvfb.sh` (ctest does that): MeshLab needs an X display even for meshlabserver.
#include "run_elastica.h"
#include "file_helpers.h"
#include "surface_distance.h"
#include "test_meshes.h"

#include <elastica/geometry.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/io/mesh_writer.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <wrap/io_trimesh/import_ply.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace elastica {
namespace {

using test::CommandResult;
CommandResult run(const std::string& command) { return test::runCommand(command); }
std::string quote(const std::string& s) { return test::quoted(s); }

const std::string kWork = PLUGIN_TEST_WORK_DIR;
const std::string kPrefix = kWork + "/meshlab-prefix";


// Reads a PLY written by meshlabserver or `elastica run` with vcglib's importer, which (unlike
// io::readMesh) also loads vertex quality and colour.
void loadOutput(const std::string& path, VcgMesh& m) {
  int mask = 0;
  ASSERT_EQ(vcg::tri::io::ImporterPLY<VcgMesh>::Open(m, path.c_str(), mask), 0) << path;
}

double diagonal(const VcgMesh& m) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (const auto& v : m.vert)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v.cP()[k]), hi[k] = std::max(hi[k], v.cP()[k]);
  return (hi - lo).norm();
}

double maxDistance(const VcgMesh& a, const VcgMesh& b) {
  double d = 0;
  for (size_t i = 0; i < a.vert.size() && i < b.vert.size(); ++i) d = std::max(d, (a.vert[i].cP() - b.vert[i].cP()).Norm());
  return d;
}

// The vertex quality (H) of `a` is not all zero, and `b`'s differs from it by at most `relative`
// of `a`'s largest |quality|.
void expectSameQuality(const VcgMesh& a, const VcgMesh& b, double relative) {
  double qMax = 0, qDiff = 0;
  for (size_t i = 0; i < a.vert.size() && i < b.vert.size(); ++i) {
    qMax = std::max(qMax, std::abs(a.vert[i].cQ()));
    qDiff = std::max(qDiff, std::abs(a.vert[i].cQ() - b.vert[i].cQ()));
  }
  EXPECT_GT(qMax, 0);
  EXPECT_LE(qDiff, relative * qMax);
}

// Writes a noisy level-2 icosphere, faces with z > 0 selected if `selectUpper`.
void writeNoisySphere(const std::string& path, unsigned seed, bool selectUpper) {
  TriMesh sphere = shapes::icosphere(1.0, 2);
  shapes::addRadialNoise(sphere, 0.05, seed);
  VcgMesh vm;
  fromTriMesh(sphere, vm);
  if (selectUpper)
    for (auto& f : vm.face)
      if (f.cP(0)[2] > 0 && f.cP(1)[2] > 0 && f.cP(2)[2] > 0) f.SetS();
  io::PlyWriteOptions w;
  w.faceFlags = selectUpper;
  io::writePly(path, vm, w);
}

int selectedFaces(const VcgMesh& m) {
  int n = 0;
  for (const auto& f : m.face) n += f.IsS() ? 1 : 0;
  return n;
}

class Meshlabserver : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::filesystem::create_directories(kWork);
    const CommandResult r =
        run(quote(PLUGIN_PREFIX_SCRIPT) + " --prefix " + quote(kPrefix) + " " + quote(PLUGIN_MODULE));
    ASSERT_EQ(r.exitCode, 0) << r.output;
  }
  void SetUp() override { ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under scripts/with-xvfb.sh (ctest does)"; }

  // The default `fairing.mlx` on `scan` (a libcgal-demo scan) with vertex noise beats MeshLab's own
  // default smoothing (defined after the fixture).
  void expectDefaultBeatsMeshLab(const std::string& scan, double noise);

  // Runs `script` on `input` with meshlabserver and with `elastica run`; loads both outputs.
  void runBoth(const std::string& input, const std::string& script, const std::string& name) {
    mlOut = dir.file(name + "_meshlab.ply");
    runOut = dir.file(name + "_run.ply");
    ml = run(kPrefix + "/bin/meshlabserver -i " + quote(input) + " -o " + quote(mlOut) + " -m vc vq ff -s " +
             quote(script));
    ASSERT_EQ(ml.exitCode, 0) << ml.output;
    ASSERT_TRUE(std::filesystem::exists(mlOut)) << ml.output;
    el = run(quote(ELASTICA_EXE) + " run -i " + quote(input) + " -o " + quote(runOut) + " -s " + quote(script));
    ASSERT_EQ(el.exitCode, 0) << el.output;
    loadOutput(mlOut, meshlab);
    loadOutput(runOut, ours);
    ASSERT_EQ(meshlab.vn, ours.vn);
    ASSERT_EQ(meshlab.fn, ours.fn);
    for (int f = 0; f < meshlab.fn; ++f)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(vcg::tri::Index(meshlab, meshlab.face[f].cV(k)), vcg::tri::Index(ours, ours.face[f].cV(k)));
    relativeDifference = maxDistance(meshlab, ours) / diagonal(ours);
    std::printf("[ %s ] meshlabserver vs elastica run: max position difference %.3g of the diagonal\n", name.c_str(),
                relativeDifference);
    EXPECT_LE(relativeDifference, 1e-5);
  }

  test::ScratchDir dir{"plugin-meshlabserver"};
  std::string mlOut, runOut;
  CommandResult ml, el;
  VcgMesh meshlab, ours;
  double relativeDifference = 0;
};

const std::string kBunny = std::string(ELASTICA_DATA_DIR) + "/bunny.ply";
const std::string kScripts = PLUGIN_TEST_SCRIPTS_DIR;
const std::string kExamples = PLUGIN_EXAMPLES_DIR;

TEST_F(Meshlabserver, FairingBunnyMatchesElasticaRun) {
  runBoth(kBunny, kScripts + "/fairing_explicit_2000_steps.mlx", "fairing");
  EXPECT_NE(ml.output.find("Discrete Elastica Fairing: 1839 -> 1839 vertices, 2000 steps"), std::string::npos)
      << ml.output;
  // The filter did something: vertices moved by far more than the agreement tolerance.
  VcgMesh input;
  io::readMesh(kBunny, input);
  EXPECT_GT(maxDistance(input, meshlab) / diagonal(input), 1e-3);
  // colorByMeanCurvature: H as quality, the same in both.
  expectSameQuality(ours, meshlab, 1e-3);
}

// Selected faces only, semi-implicit, one subdivision: connectivity changes, the selection follows.
TEST_F(Meshlabserver, SelectedSubdividedFairingMatchesElasticaRun) {
  const std::string input = dir.file("noisy_selected.ply");
  writeNoisySphere(input, 11, /*selectUpper=*/true);
  VcgMesh in;
  io::readMesh(input, in);
  ASSERT_GT(selectedFaces(in), 0);

  runBoth(input, kScripts + "/fairing_selected_semi_implicit_subdivided.mlx", "selected");
  // Only the selection is refined 1-to-4; the faces along it split to stay conforming.
  EXPECT_EQ(selectedFaces(ours), 4 * selectedFaces(in));
  EXPECT_GT(ours.fn, in.fn + 3 * selectedFaces(in));
  EXPECT_LT(ours.fn, 4 * in.fn);
  EXPECT_EQ(selectedFaces(meshlab), selectedFaces(ours));
}

TEST_F(Meshlabserver, CurvatureExampleMatchesElasticaRun) {
  runBoth(kBunny, kExamples + "/curvature.mlx", "curvature");
  EXPECT_EQ(relativeDifference, 0);  // positions untouched
  for (int i = 0; i < ours.vn; ++i) EXPECT_EQ(ours.vert[i].cC(), meshlab.vert[i].cC()) << "vertex " << i;
  expectSameQuality(ours, meshlab, 1e-5);
}

// The shipped example lists every parameter (meshlabserver aborts otherwise) at its default, so it
// gives what the dialog's OK gives: featureSize -1 is the mesh's own amount ("auto"), a fairer
// surface of the same model, in both meshlabserver and `elastica run`.
TEST_F(Meshlabserver, FairingExampleRunsAtTheDefault) {
  const std::string input = dir.file("noisy.ply");
  writeNoisySphere(input, 3, /*selectUpper=*/false);
  runBoth(input, kExamples + "/fairing.mlx", "example");
  EXPECT_NE(ml.output.find("(faired to the feature size)"), std::string::npos) << ml.output;
  EXPECT_NE(ml.output.find("mean edge lengths, auto)"), std::string::npos) << ml.output;
  EXPECT_NE(el.output.find("mean edge lengths, auto)"), std::string::npos) << el.output;
}

// The default amount against MeshLab's own default smoothing, both run by Debian's meshlabserver,
// on a named scan with 3-D vertex noise (uniform in a ball of `noise` mean edges, as bench/add_noise
// makes it): the default `fairing.mlx` ends closer to the clean scan (the mean of both sampled RMS
// distances) than Taubin Smooth (lambda 0.5, mu -0.53, 10 steps) and HC Laplacian Smooth at their
// defaults. (Not so on every scan: docs/options.md, "The default amount".)
void Meshlabserver::expectDefaultBeatsMeshLab(const std::string& scan, double noise) {
  const std::string clean = std::string(ELASTICA_SAMPLE_MESH_DIR) + "/" + scan + ".off";
  const std::string input = dir.file(scan + "_noisy.ply");
  const TriMesh original = io::readMesh(clean).mesh;
  const TriMesh noisy = test::ballJittered(
      original, noise * meanEdgeLength(Topology(original.vertexCount(), original.faces), original.positions), 1);
  io::writePly(input, noisy, {}, true);
  auto script = [&](const std::string& name, const std::string& filter) {
    test::writeText(dir.file(name), "<!DOCTYPE FilterScript>\n<FilterScript>\n" + filter + "\n</FilterScript>\n");
    return dir.file(name);
  };
  const std::string taubin = script("taubin.mlx",
      "<filter name=\"Taubin Smooth\"><Param type=\"RichFloat\" value=\"0.5\" name=\"lambda\"/><Param type=\"RichFloat\" "
      "value=\"-0.53\" name=\"mu\"/><Param type=\"RichInt\" value=\"10\" name=\"stepSmoothNum\"/><Param "
      "type=\"RichBool\" value=\"false\" name=\"Selected\"/></filter>");
  const std::string hc = script("hc.mlx", "<filter name=\"HC Laplacian Smooth\"/>");
  const double diagonal = boundingBoxDiagonal(original.positions);
  auto distance = [&](const std::string& script, const std::string& name) {
    const std::string out = dir.file(scan + "_" + name + ".ply");
    const CommandResult r = run(kPrefix + "/bin/meshlabserver -i " + quote(input) + " -o " + quote(out) + " -s " + quote(script));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const TriMesh result = io::readMesh(out).mesh;
    const double d =
        (bench::sampledDistance(result, original, 3).rms + bench::sampledDistance(original, result, 3).rms) / (2 * diagonal);
    std::printf("[ %s ] %.3e of the diagonal from the clean %s\n", name.c_str(), d, scan.c_str());
    return d;
  };
  const double input0 =
      (bench::sampledDistance(noisy, original, 3).rms + bench::sampledDistance(original, noisy, 3).rms) / (2 * diagonal);
  const double ours = distance(kExamples + "/fairing.mlx", "elastica");
  EXPECT_LT(ours, 0.95 * input0);
  EXPECT_LT(ours, distance(taubin, "taubin"));
  EXPECT_LT(ours, distance(hc, "hc"));
}

TEST_F(Meshlabserver, DefaultBeatsMeshLabsSmoothingOnANoisyBull) { expectDefaultBeatsMeshLab("bull", 0.3); }

// The elk: Taubin's win while the amount's filter took the noisy scan's cotangents (1.99e-3
// against 1.94e-3); the uniform operators of a rough scan (app/fairing_amount.h) bring it to 1.81e-3,
// twiced to 1.75e-3.
TEST_F(Meshlabserver, DefaultBeatsMeshLabsSmoothingOnANoisyElk) { expectDefaultBeatsMeshLab("elk", 0.3); }

// The elk with noise of 0.1 edge (roughness 0.068): on the cotangents it ended farther from the
// clean scan than its noisy input (9.20e-4 against 8.81e-4); the twiced uniform operators, from
// roughness 0.045, bring it to 8.23e-4 (Taubin 1.61e-3).
TEST_F(Meshlabserver, DefaultBeatsMeshLabsSmoothingOnALittleNoisyElk) { expectDefaultBeatsMeshLab("elk", 0.1); }

// The bunny with its flank cut away: the hole is filled, the new faces (only they) selected.
TEST_F(Meshlabserver, FillHolesExampleMatchesElasticaRun) {
  const std::string input = std::string(ELASTICA_DATA_DIR) + "/bunny_flank_hole.ply";
  runBoth(input, kExamples + "/fill_holes.mlx", "fill");
  VcgMesh in;
  io::readMesh(input, in);
  EXPECT_GT(ours.fn, in.fn);
  EXPECT_EQ(selectedFaces(ours), ours.fn - in.fn);
  EXPECT_EQ(selectedFaces(meshlab), selectedFaces(ours));
  // The original vertices stay where they were (up to float storage).
  for (int i = 0; i < in.vn; ++i) ASSERT_LE((in.vert[i].cP() - meshlab.vert[i].cP()).Norm(), 1e-6 * diagonal(in)) << i;
  EXPECT_NE(ml.output.find("Fill Holes with Discrete Elastica: filled 1 of 1 holes"), std::string::npos) << ml.output;
}

// CGAL's elephant with 106 holes, as MeshLab loads it: the 65 points where two fans of faces meet
// are two vertices each, so some hole borders pass twice through one point. The filter splits
// those borders, welds the copies in MeshLab's mesh, and the result is one closed manifold
// surface of the intact elephant's genus.
TEST_F(Meshlabserver, FillHolesClosesCgalsElephantWithHoles) {
  const std::string input = std::string(ELASTICA_SAMPLE_MESH_DIR) + "/elephant-with-holes.off";
  const std::string out = dir.file("elephant_filled.ply");
  const CommandResult r = run(kPrefix + "/bin/meshlabserver -i " + quote(input) + " -o " + quote(out) + " -s " +
                              quote(kExamples + "/fill_holes.mlx"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("merged 65 pairs of vertex copies"), std::string::npos) << r.output;
  VcgMesh filled, intact;
  const io::ReadReport report = io::readMesh(out, filled);
  EXPECT_EQ(report.duplicateVerticesMerged, 0);    // no copies left at one point
  EXPECT_EQ(report.nonManifoldVerticesSplit, 0);   // and no fans meeting at a point
  io::readMesh(std::string(ELASTICA_SAMPLE_MESH_DIR) + "/elephant.off", intact);
  const TriMesh a = toTriMesh(filled), b = toTriMesh(intact);
  const Topology ta(a.vertexCount(), a.faces), tb(b.vertexCount(), b.faces);
  EXPECT_EQ(ta.boundaryEdgeCount(), 0);
  EXPECT_EQ(ta.eulerCharacteristic(), tb.eulerCharacteristic());
}

// Unsuitable input: meshlabserver reports our message in its log, fails, and writes nothing.
TEST_F(Meshlabserver, NonManifoldInputFailsWithMessage) {
  TriMesh mesh = shapes::icosphere(1.0, 1);
  mesh.positions.push_back(Vec3(2, 2, 2));
  mesh.faces.push_back({mesh.faces[0][0], mesh.faces[0][1], mesh.vertexCount() - 1});
  VcgMesh vm;
  fromTriMesh(mesh, vm);
  const std::string input = dir.file("fin.ply"), out = dir.file("fin_out.ply");
  io::writePly(input, vm, {});
  const CommandResult r = run(kPrefix + "/bin/meshlabserver -i " + quote(input) + " -o " + quote(out) + " -s " +
                              quote(kScripts + "/fairing_explicit_2000_steps.mlx"));
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("Discrete Elastica Fairing: Topology: non-manifold edge"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace elastica
