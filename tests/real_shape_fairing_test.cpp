// The default fair() on whole scans from Debian's libcgal-demo that the flow was not designed on
// (scripts/setup.sh fetches them): four-legged animals and a knotted tube. Genus 0 must end as a
// round sphere with a true "converged"; a knotted torus cannot become a Clifford torus without
// passing through itself, so it must end without crossing and say why it stopped.
#include "sample_meshes.h"
#include "self_intersections.h"
#include "shape_measures.h"

#include <elastica/fairing.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/topology.h>
#include <elastica/vcg_adapter.h>
#include <elastica/vcg_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace elastica {
namespace {

using test::readSample;

int genus(const TriMesh& m) { return (2 - Topology(m.vertexCount(), m.faces).eulerCharacteristic()) / 2; }

class RealShape : public ::testing::TestWithParam<const char*> {};

// Measured at this commit (attempts, seconds on this 2-core machine, E): cow 90, 4 s, 25.10;
// dino 170, 18 s, 25.11; bull 143, 24 s, 25.12; spreads 0.01–0.06 %. The semi-implicit scheme
// stopped at the 60 s limit on all three (E 198, 652, 847). Bounds: the issue's.
TEST_P(RealShape, GenusZeroScanBecomesARoundSphere) {
  TriMesh m = readSample(GetParam());
  ASSERT_EQ(genus(m), 0);
  const bool inputCrossed = test::selfIntersections(m) > 0;  // the cow's does (137 faces)
  const FlowReport r = fair(m);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_LE(r.steps, 200);
  EXPECT_EQ(genus(m), 0);
  if (!inputCrossed) {
    EXPECT_EQ(test::selfIntersections(m), 0);
  }
  EXPECT_LT(test::fittedRadii(m).spread(), 0.01);
  EXPECT_NEAR(test::energyOf(m), 8 * M_PI, 0.03 * 8 * M_PI);
  EXPECT_NEAR(r.energyFinal, test::energyOf(m), 1e-9 * r.energyFinal);
}

INSTANTIATE_TEST_SUITE_P(LibcgalDemo, RealShape, ::testing::Values("cow.off", "dino.off", "bull.off"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param).substr(0, std::string(info.param).find('.'));
                         });

// knot1 (a knotted tube, genus 1): the elastica flow swells the tube until it presses against
// itself; the embedding guard holds the vertices that would cross, step after step. The stop says
// so (not "converged", not "stalled"), in few attempts (67 measured), and the output keeps its
// genus and does not cross itself.
TEST(RealShapes, KnottedTubeStopsAtSelfContactWithoutCrossing) {
  TriMesh m = readSample("knot1.off");
  ASSERT_EQ(genus(m), 1);
  ASSERT_EQ(test::selfIntersections(m), 0);
  const double before = test::energyOf(m);
  const FlowReport r = fair(m);
  EXPECT_EQ(r.stop, StopReason::SelfContact);
  EXPECT_LE(r.steps, 200);
  EXPECT_EQ(genus(m), 1);
  EXPECT_EQ(test::selfIntersections(m), 0);
  EXPECT_LT(test::energyOf(m), 0.7 * before);
}

}  // namespace
}  // namespace elastica
