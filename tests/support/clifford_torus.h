// SPDX-License-Identifier: GPL-3.0-or-later
// The torus R/r = 3 faired to the Clifford torus, which each scheme's test checks alike (gtest
// checks: for the test suites only, not the benchmarks).
#pragma once

#include "shape_measures.h"

#include <elastica/fairing.h>
#include <elastica/shapes.h>

#include <gtest/gtest.h>

#include <cmath>

namespace elastica::test {

/// Fairs the 96×32 torus R/r = 3 into `m` with `scheme`, and expects the Clifford torus R/r = √2
/// (E = 8π²): converged, R/r within 3 % of √2, E within 2 % of 8π². Returns the run's report.
inline FlowReport fairToCliffordTorus(Scheme scheme, TriMesh& m) {
  m = shapes::torus(3, 1, 96, 32);
  FlowOptions opt;
  opt.scheme = scheme;
  const FlowReport r = fair(m, opt);
  EXPECT_EQ(r.stop, StopReason::Converged);
  EXPECT_NEAR(aspectRatio(m), std::sqrt(2.0), 0.03 * std::sqrt(2.0));
  EXPECT_NEAR(energyOf(m), 8 * M_PI * M_PI, 0.02 * 8 * M_PI * M_PI);
  return r;
}

}  // namespace elastica::test
