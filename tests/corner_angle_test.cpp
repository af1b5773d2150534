// SPDX-License-Identifier: GPL-3.0-or-later
// The angle at a corner (operators/corner_angle.h): exact cases, the ends of the range, and the
// smallest-angle measure built on it.
#include <elastica/mesh_quality.h>
#include "operators/corner_angle.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace elastica;

TEST(CornerAngle, KnownTriangles) {
  EXPECT_DOUBLE_EQ(cornerAngle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 2, 0)), M_PI / 2);
  EXPECT_NEAR(cornerAngle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, std::sqrt(3.0) / 2, 0)), M_PI / 3, 1e-15);
  EXPECT_NEAR(smallestAngleDegrees(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, std::sqrt(3.0) / 2, 0)), 60, 1e-12);
  // The angles of a triangle sum to π.
  const Vec3 a(0.3, -1, 2), b(1.7, 0.2, -0.4), c(-0.5, 0.9, 0.1);
  EXPECT_NEAR(cornerAngle(a, b, c) + cornerAngle(b, c, a) + cornerAngle(c, a, b), M_PI, 1e-14);
}

// atan2 keeps its digits where acos of a dot product near ±1 loses them.
TEST(CornerAngle, AccurateNearZeroAndPi) {
  const double eps = 1e-9;
  EXPECT_NEAR(angleBetween(Vec3(1, 0, 0), Vec3(1, eps, 0)), eps, 1e-20);
  EXPECT_NEAR(angleBetween(Vec3(1, 0, 0), Vec3(-1, eps, 0)), M_PI - eps, 1e-15);
  EXPECT_EQ(angleBetween(Vec3(0, 0, 0), Vec3(1, 0, 0)), 0.0);  // a zero edge: no angle
}
