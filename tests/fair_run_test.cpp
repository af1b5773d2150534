// SPDX-License-Identifier: GPL-3.0-or-later
// A region's fair through the application layer (app/filter_run.h), the path of every face: it
// checks the whole mesh and measures its energy a piece at a time, building no Topology of the
// whole mesh, and refuses what a whole run refuses, with the same message.
#include <elastica/app/filter_run.h>
#include <elastica/errors.h>
#include <elastica/face_set.h>
#include <elastica/mesh_curvature.h>
#include <elastica/shapes.h>
#include <elastica/topology.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace elastica::app {
namespace {

// A wavy 240 × 240 grid (58,081 vertices, numbered row by row): several pieces of the region run's
// check, each a band of rows, none holding the whole mesh.
TriMesh largeMesh() {
  TriMesh m = shapes::grid(240, 240, 0.01);
  for (Vec3& p : m.positions) p.z() = 0.05 * std::sin(7 * p.x()) * std::cos(5 * p.y());
  return m;
}

// The faces near its centre.
FaceSet centreFaces(const TriMesh& m) {
  std::vector<int> centre;
  for (int f = 0; f < m.faceCount(); ++f) {
    const Face& t = m.faces[f];
    const Vec3 c = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3;
    if ((c - Vec3(1.2, 1.2, c.z())).norm() < 0.1) centre.push_back(f);
  }
  return FaceSet(centre);
}

FlowOptions twoSteps() {
  FlowOptions opt;
  opt.maxSteps = 2;
  return opt;
}

// The message a run throws, or "" if it ran.
std::string refusal(const TriMesh& m, std::optional<FaceSet> region) {
  try {
    runFairing(m, std::move(region), twoSteps(), false);
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return "";
}

TEST(FairRun, RegionRunMeasuresTheWholeMeshWithoutItsTopology) {
  const TriMesh mesh = largeMesh();
  const FaceSet region = centreFaces(mesh);
  ASSERT_GT(region.faces.size(), 50u);
  Topology::resetLargestBuilt();
  const FairingResult r = runFairing(mesh, region, twoSteps(), false);
  EXPECT_GT(r.report.steps, 0);
  EXPECT_LT(Topology::largestBuilt(), mesh.vertexCount());
  const double whole = measureCurvature(mesh).energy;
  EXPECT_NEAR(r.meshEnergyBefore, whole, 1e-12 * whole);  // the sums' order differs, not their terms
}

TEST(FairRun, RegionRunRefusesWhatAWholeRunRefuses) {
  const TriMesh mesh = largeMesh();
  const FaceSet region = centreFaces(mesh);
  TriMesh flipped = mesh;
  std::swap(flipped.faces[5][0], flipped.faces[5][1]);
  TriMesh bowTie = mesh;  // a triangle hung on vertex 7: two fans there
  bowTie.positions.push_back(Vec3(2, 2, 2));
  bowTie.positions.push_back(Vec3(2, 3, 2));
  bowTie.faces.push_back({7, bowTie.vertexCount() - 2, bowTie.vertexCount() - 1});
  TriMesh fin = mesh;  // a third face on an edge: a non-manifold edge, named in the mesh's numbers
  fin.positions.push_back(Vec3(2, 2, 2));
  fin.faces.push_back({fin.faces[70000][0], fin.faces[70000][1], fin.vertexCount() - 1});
  for (const TriMesh* m : {&flipped, &bowTie, &fin}) {
    const std::string asWhole = refusal(*m, std::nullopt);
    ASSERT_FALSE(asWhole.empty());
    EXPECT_EQ(refusal(*m, region), asWhole);
  }
  EXPECT_NE(refusal(flipped, region).find("not consistently oriented"), std::string::npos);
  EXPECT_NE(refusal(bowTie, region).find("non-manifold vertices"), std::string::npos);
  EXPECT_NE(refusal(fin, region).find("non-manifold edge"), std::string::npos);
}

// The default amount's roughness (fairing_amount.h): a sphere's curvature cancels (a clean
// icosphere reads as smooth as a clean scan), radial vertex noise does not; the clean sphere keeps
// two 25 %-quantile edges and the cotangents, the noisy one the uniform operators and
// graphAmountEdges(ρ) mean edges (more than two quantile edges), each rounded to the 6 digits that print.
TEST(FairingAmount, RoughnessSeesNoiseNotCurvature) {
  TriMesh sphere = shapes::icosphere(1.0, 4);
  std::vector<double> lengths;
  for (const Face& t : sphere.faces)
    for (int k = 0; k < 3; ++k) lengths.push_back((sphere.positions[t[k]] - sphere.positions[t[(k + 1) % 3]]).norm());
  std::sort(lengths.begin(), lengths.end());
  const double q25 = lengths[static_cast<std::size_t>(std::floor(0.25 * double(lengths.size() - 1)))];
  const double clean = surfaceRoughness(sphere, nullptr);
  EXPECT_LT(clean, 0.02);
  EXPECT_EQ(autoFeatureSize(sphere, nullptr), roundedAmount(2 * q25));
  EXPECT_EQ(autoAmount(sphere, nullptr).operators, AmountOperators::Cotangent);
  TriMesh noisy = sphere;
  shapes::addRadialNoise(noisy, 0.3 * meanFaceEdge(sphere, nullptr), 3);
  const double rough = surfaceRoughness(noisy, nullptr);
  EXPECT_GT(rough, kCleanRoughness);
  EXPECT_GT(autoFeatureSize(noisy, nullptr), 2 * q25);
  const AutoAmount noisyAmount = autoAmount(noisy, nullptr);
  EXPECT_EQ(noisyAmount.operators, AmountOperators::Graph);
  EXPECT_EQ(noisyAmount.featureSize, roundedAmount(graphAmountEdges(rough) * meanFaceEdge(noisy, nullptr)));
  EXPECT_EQ(exactDecimal(roundedAmount(0.123456789)), "0.123457");
  EXPECT_EQ(std::stod(exactDecimal(0.1 / 3)), 0.1 / 3);
  std::printf("roughness: clean icosphere %.4f, radial noise of 0.3 edge %.4f\n", clean, rough);
}

// The uniform operators' gates: rough (above kGraphRoughness) and no long slivers (mean edge at
// most kGraphMaxEdgeRatio quantile edges; the CAD part joint's 6.6 keeps the cotangents).
TEST(FairingAmount, UniformOperatorsOnlyForARoughEvenMesh) {
  EXPECT_EQ(amountOperatorsFor(0.15, 1.2, 1.0), AmountOperators::Graph);
  EXPECT_EQ(amountOperatorsFor(0.15, 4.0, 1.0), AmountOperators::Graph);
  EXPECT_EQ(amountOperatorsFor(0.15, 6.6, 1.0), AmountOperators::Cotangent);
  EXPECT_EQ(amountOperatorsFor(0.05, 1.2, 1.0), AmountOperators::Graph);  // noise of 0.1 edge
  EXPECT_EQ(amountOperatorsFor(kGraphRoughness, 1.2, 1.0), AmountOperators::Cotangent);
  EXPECT_EQ(amountOperatorsFor(0.02, 1.2, 1.0), AmountOperators::Cotangent);
  EXPECT_LT(graphAmountEdges(0.15), graphAmountEdges(0.48));  // grows with the roughness
  EXPECT_EQ(graphAmountEdges(0.01), graphAmountEdges(kGraphRoughness));
}

}  // namespace
}  // namespace elastica::app
