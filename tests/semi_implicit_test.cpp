// The semi-implicit scheme's own behaviour (Scheme::SemiImplicit: the stiff fourth-order part solved
// implicitly, adaptive τ, accepted steps only): the torus all the way to the Clifford torus, the
// drift held to the step's rules, and what it refuses. Its shared tests with the explicit scheme
// are in flow_scheme_test.cpp.
#include "shape_measures.h"

#include <elastica/errors.h>
#include <elastica/fairing.h>
#include <elastica/shapes.h>
#include <elastica/subdivision.h>

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

using namespace elastica;
using test::aspectRatio;
using test::energyOf;

// Torus R/r = 3 to the Clifford torus R/r = √2 (E = 8π²), stopping at the plateau. The discrete
// energy underestimates at O(h²) and the flow's discrete minimum sits below the sampled Clifford
// torus: measured −3.6 % at 48×16 (768 vertices; the sampled Clifford torus of that resolution:
// −2.4 %), −1.7 % at 64×32 (2,048), −1.1 % at 96×32 (3,072; R/r 1.408, about 60 steps). This
// resolution is the coarsest that meets the 2 % (asserted: R/r within 3 % of √2, E within 2 %).
TEST(SemiImplicit, TorusReachesCliffordTorus) {
  TriMesh m = shapes::torus(3, 1, 96, 32);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_LT(r.steps, 1000);
  EXPECT_NEAR(aspectRatio(m), std::sqrt(2.0), 0.03 * std::sqrt(2.0));
  EXPECT_NEAR(energyOf(m), 8 * M_PI * M_PI, 0.02 * 8 * M_PI * M_PI);
  EXPECT_NEAR(r.energyFinal, energyOf(m), 1e-9 * energyOf(m));
}

// The tangential drift after an accepted step obeys the step's rules (no face turned over, E not
// above the step's allowance): on the subdivided tubular cage an unchecked drift pass once folded
// the mesh and lifted E from 523 to 10⁶ in one "accepted" step.
TEST(SemiImplicit, DriftKeepsTheStepRules) {
  TriMesh m = shapes::frameCage(2, 1);
  subdivideMidpoint(m);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  opt.subdivisionLevels = 1;
  opt.maxSteps = 300;
  opt.remesh = false;  // remeshing and edge flips change E between steps, as subdivision does
  std::vector<std::pair<int, double>> seen;  // (level, E) after every accepted step
  opt.progress = [&](const FlowProgress& p) {
    seen.emplace_back(p.level, p.energy);
    return true;
  };
  fair(m, opt);
  ASSERT_GT(seen.size(), 20u);
  EXPECT_EQ(seen.back().first, 1);
  for (size_t k = 1; k < seen.size(); ++k) {
    if (seen[k].first != seen[k - 1].first) continue;  // subdivision changes E
    EXPECT_LE(seen[k].second, seen[k - 1].second * (1 + 1e-4) + 1e-9) << "accepted step " << k;
  }
}

TEST(SemiImplicit, BilaplacianIsExplicitOnly) {
  TriMesh m = shapes::icosphere(1.0, 1);
  FlowOptions opt;
  opt.scheme = Scheme::SemiImplicit;
  opt.flow = FlowType::Bilaplacian;
  EXPECT_THROW(fair(m, opt), InvalidInputError);
}
