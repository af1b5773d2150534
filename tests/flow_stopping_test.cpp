// SPDX-License-Identifier: GPL-3.0-or-later
// The stopping tolerances mean the same in both schemes: FlowOptions::energyTolerance (the
// relative energy change per unit of normalised time t/A²) ends an explicit and a semi-implicit
// run alike. Before, the semi-implicit scheme read only its own plateau test and silently ignored
// the energy tolerance (CLI --energy-tol, MeshLab's "Energy tolerance").
#include <elastica/fairing.h>
#include <elastica/shapes.h>

#include <gtest/gtest.h>

using namespace elastica;

namespace {

class EnergyTolerance : public ::testing::TestWithParam<Scheme> {};

// A run on a noisy 162-vertex sphere with energy tolerance `tol` (no subdivision).
FlowReport runWith(Scheme scheme, double tol) {
  TriMesh m = shapes::icosphere(1.0, 2);
  shapes::addRadialNoise(m, 0.05, 1);
  FlowOptions opt;
  opt.scheme = scheme;
  opt.energyTolerance = tol;
  opt.plateauTolerance = 0;  // semi-implicit: only the energy tolerance can end the run early
  opt.maxSteps = scheme == Scheme::Explicit ? 20000 : 100;
  return fair(m, opt);
}

}  // namespace

// A tolerance so loose that the first rate measured is below it stops the run at its first check
// (explicit: checkInterval steps; semi-implicit: the first full window, 10 accepted steps), while
// tolerance 0 lets the same run go on (explicit: to its step limit; semi-implicit: until its
// energy stops falling, 16 accepted steps later on this mesh).
TEST_P(EnergyTolerance, LooseToleranceStopsAtTheFirstCheck) {
  const bool explicitScheme = GetParam() == Scheme::Explicit;
  const FlowReport loose = runWith(GetParam(), 1e6);
  const FlowReport strict = runWith(GetParam(), 0);
  ASSERT_EQ(loose.stages.size(), 1u);
  ASSERT_EQ(strict.stages.size(), 1u);
  EXPECT_EQ(loose.stop, StopReason::Converged);
  EXPECT_EQ(loose.stages[0].steps, explicitScheme ? FlowOptions{}.checkInterval : 10);
  EXPECT_GE(strict.stages[0].steps, explicitScheme ? 20000 : 20);
  EXPECT_LT(strict.energyFinal, loose.energyFinal);
}

INSTANTIATE_TEST_SUITE_P(BothSchemes, EnergyTolerance, ::testing::Values(Scheme::Explicit, Scheme::SemiImplicit),
                         [](const ::testing::TestParamInfo<Scheme>& info) {
                           return info.param == Scheme::Explicit ? "Explicit" : "SemiImplicit";
                         });
