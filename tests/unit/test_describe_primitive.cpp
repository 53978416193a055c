// Tests of describe_primitive: the log line a user reads, the fits' round-off shown as 0.
#include "common/base/describe_primitive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace primitive_edit;

// The cylinder the edit tool's GUI test fits to an exact hole: its axis and axis point carry round-off.
TEST(DescribePrimitive, RoundOffReadsAsZero)
{
  Primitive p;
  p.type = PrimitiveType::Cylinder;
  p.origin = Eigen::Vector3d(1.777602342e-16, 6.880933869e-17, -1.669671346e-17);
  p.axis = Eigen::Vector3d(-6.984947206e-17, 5.984022286e-17, 1);
  p.radius = 7;
  EXPECT_EQ(describe_primitive(p), "Cylinder: axis point (0, 0, 0), axis (0, 0, 1), radius 7, diameter 14");
}

// Small values that are values stay: a direction 1e-6 off an axis, a position 1e-9 of the size off a plane.
TEST(DescribePrimitive, SmallValuesThatMeasureSomethingStay)
{
  Primitive p;
  p.type = PrimitiveType::Plane;
  p.axis = Eigen::Vector3d(1e-6, 0, 1).normalized();
  p.origin = Eigen::Vector3d(2e-9, -3e-17, 2);
  EXPECT_EQ(describe_primitive(p), "Plane: normal (1e-06, 0, 1), offset 2, point (2e-09, 0, 2)");
  EXPECT_EQ(shown_value(-1e-13, 1.0), 0.0);
  EXPECT_FALSE(std::signbit(shown_value(-1e-13, 1.0))); // no "-0"
  EXPECT_EQ(shown_value(1e-11, 1.0), 1e-11);
  EXPECT_TRUE(std::isnan(shown_value(std::numeric_limits<double>::quiet_NaN(), 1.0)));
}

TEST(DescribePrimitive, SizeIsTheLargestOfPositionAndRadii)
{
  Primitive p;
  p.type = PrimitiveType::Torus;
  p.origin = Eigen::Vector3d(3, 4, 0);
  p.radius = 2;
  p.minor_radius = 0.5;
  EXPECT_EQ(primitive_size(p), 5);
  p.radius = -9; // an invalid primitive is still described, and sized by its magnitudes
  EXPECT_EQ(primitive_size(p), 9);
}

} // namespace
