// SPDX-License-Identifier: GPL-3.0-or-later
// The default fair() on whole scans from Debian's libcgal-demo that the flow was not designed on
// (scripts/setup.sh fetches them): four-legged animals and a knotted tube. Genus 0 must end as a
// round sphere with a true "converged"; a knotted torus cannot become a Clifford torus without
// passing through itself, so it must end without crossing and say why it stopped.
#include "sample_meshes.h"
#include "self_intersections.h"
#include "shape_measures.h"

#include <elastica/fairing.h>
#include <elastica/io/mesh_reader.h>
#include <elastica/subdivision.h>
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

// A scan and the attempts its default fair() may take.
struct Scan {
  const char* file;
  long long attempts;
};

class RealShape : public ::testing::TestWithParam<Scan> {};

// Attempts are the same on any thread count and CPU (support/parallel.h, flow/spd_solver.h), but
// they follow every rounding of the flow's arithmetic: regrouping one sum moved the dino from
// 160–179 to 203 attempts, another factorisation's rounding the cow from 136 to 87. Measured with
// the fixed reduction chunks and CHOLMOD's simplicial factorisation, at 1 and 2 threads alike:
// cow 87, dino 198, bull 145 attempts, each converged round. The bound is the genus-0 promise,
// 200 attempts, where the flow meets it with room; the dino, at 198, is bounded at 250 until the
// flow's larger steps (issue "handles") bring it well under 200.
TEST_P(RealShape, GenusZeroScanBecomesARoundSphere) {
  TriMesh m = readSample(GetParam().file);
  ASSERT_EQ(genus(m), 0);
  const bool inputCrossed = test::selfIntersections(m) > 0;  // the cow's does (137 faces)
  const FlowReport r = fair(m);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_LE(r.steps, GetParam().attempts);
  EXPECT_EQ(genus(m), 0);
  if (!inputCrossed) {
    EXPECT_EQ(test::selfIntersections(m), 0);
  }
  EXPECT_LT(test::fittedRadii(m).spread(), 0.01);
  EXPECT_NEAR(test::energyOf(m), 8 * M_PI, 0.03 * 8 * M_PI);
  EXPECT_NEAR(r.energyFinal, test::energyOf(m), 1e-9 * r.energyFinal);
}

INSTANTIATE_TEST_SUITE_P(LibcgalDemo, RealShape,
                         ::testing::Values(Scan{"cow.off", 200}, Scan{"dino.off", 250}, Scan{"bull.off", 200}),
                         [](const ::testing::TestParamInfo<Scan>& info) {
                           const std::string file = info.param.file;
                           return file.substr(0, file.find('.'));
                         });

// knot1 (a knotted tube, genus 1): the elastica flow swells the tube until it presses against
// itself; the embedding guard holds the vertices that would cross, step after step. The stop says
// so (not "converged", not "stalled"), in few attempts, and the output keeps its genus and does
// not cross itself. A self-contact end is a result as a converged one is: resolved (Loop-subdivided
// once, E within 2 %; measured: 57 attempts, E 263.57, Loop-1 +1.5 %, after one refinement where
// the gap was; +4.5 % before the check applied to it).
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
  const double energy = test::energyOf(m);
  EXPECT_LT(energy, 0.7 * before);
  TriMesh loop = m;
  subdivideLoop(loop);
  EXPECT_LE(test::energyOf(loop), 1.02 * energy);
}

// Scans and a CAD part with handles (issue 40): the default fair() must end with a true stop, on
// a resolved state (Loop-subdivided once, E within 2 %), below the genus bound
// 32π + 8π(g − 1), with its genus and no new crossing face, within 300 attempts. Measured with the
// CLI at OMP_NUM_THREADS=1 and 2 (byte-identical outputs; attempts, E, Loop-1 E): elephant
// (genus 3) 221, 141.45, +0.9 %; joint (genus 2, a CAD part of 221 vertices) 158, 112.41, +1.2 %;
// elk (genus 1, its input crosses itself at 11 faces) 57, 78.80, +1.0 %. Main took 1,582, 791
// and 406 before the handles' rules (issue 40).
struct Handles {
  const char* file;
  int genus;
  long long attempts;
};

class RealShapeWithHandles : public ::testing::TestWithParam<Handles> {};

TEST_P(RealShapeWithHandles, ReachesAResolvedFairShapeWithItsHandles) {
  TriMesh m = readSample(GetParam().file);
  const int g = GetParam().genus;
  ASSERT_EQ(genus(m), g);
  const int crossedBefore = test::selfIntersections(m);  // the elk's input: 11 faces
  const FlowReport r = fair(m);
  EXPECT_TRUE(r.stop == StopReason::Converged || r.stop == StopReason::SelfContact) << static_cast<int>(r.stop);
  EXPECT_LE(r.steps, GetParam().attempts);
  EXPECT_EQ(genus(m), g);
  EXPECT_LE(test::selfIntersections(m), crossedBefore);
  const double energy = test::energyOf(m);
  EXPECT_NEAR(r.energyFinal, energy, 1e-9 * energy);
  EXPECT_LT(energy, 32 * M_PI + 8 * M_PI * (g - 1));
  TriMesh loop = m;
  subdivideLoop(loop);
  EXPECT_LE(test::energyOf(loop), 1.02 * energy);
}

INSTANTIATE_TEST_SUITE_P(LibcgalDemo, RealShapeWithHandles,
                         ::testing::Values(Handles{"elephant.off", 3, 300}, Handles{"joint.off", 2, 300},
                                           Handles{"elk.off", 1, 300}),
                         [](const ::testing::TestParamInfo<Handles>& info) {
                           const std::string file = info.param.file;
                           return file.substr(0, file.find('.'));
                         });

}  // namespace
}  // namespace elastica
