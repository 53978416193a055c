// Tests of the sharp-edge math: closest_point_on_intersection and common_point_of_primitives.
#include "common/base/constants.h"
#include "common/geometry/closest_point_on_intersection.h"
#include "common/geometry/common_point_of_primitives.h"
#include "test_fit_data.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace primitive_edit;
using namespace test_fit;

namespace {

// Brute force: points of the curve found by plain Newton-to-feasibility from many random starts around p
// (no nearest-point logic involved); the smallest distance from p among them.
double brute_force_curve_distance(const Primitive& a, const Primitive& b, const Eigen::Vector3d& p, double radius)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double best = std::numeric_limits<double>::infinity();
  for (int s = 0; s < 1500; ++s) {
    Eigen::Vector3d x = p + radius * Eigen::Vector3d(u(rng), u(rng), u(rng));
    for (int it = 0; it < 15; ++it) {
      const PrimitiveProjection pa = project_onto_primitive(a, x);
      const PrimitiveProjection pb = project_onto_primitive(b, x);
      Eigen::Matrix<double, 2, 3> j;
      j.row(0) = pa.normal.transpose();
      j.row(1) = pb.normal.transpose();
      const Eigen::Vector2d f(pa.signed_distance, pb.signed_distance);
      x -= j.transpose() * (j * j.transpose()).inverse() * f;
    }
    if (std::abs(signed_distance_to_primitive(a, x)) < 1e-9 && std::abs(signed_distance_to_primitive(b, x)) < 1e-9)
      best = std::min(best, (x - p).norm());
  }
  return best;
}

// x lies on both surfaces and x - p is orthogonal to the curve (in the span of the two normals).
void expect_on_curve_and_orthogonal(const Primitive& a, const Primitive& b, const Eigen::Vector3d& p,
                                    const Eigen::Vector3d& x)
{
  const PrimitiveProjection pa = project_onto_primitive(a, x);
  const PrimitiveProjection pb = project_onto_primitive(b, x);
  EXPECT_LT(std::abs(pa.signed_distance), 1e-9);
  EXPECT_LT(std::abs(pb.signed_distance), 1e-9);
  const Eigen::Vector3d tangent = pa.normal.cross(pb.normal).normalized();
  EXPECT_LT(std::abs(tangent.dot(x - p)), 1e-9);
}

void expect_nearest_on_curve(const Primitive& a, const Primitive& b, const Eigen::Vector3d& p)
{
  Eigen::Vector3d x;
  ASSERT_TRUE(closest_point_on_intersection(a, b, p, 10.0, x));
  expect_on_curve_and_orthogonal(a, b, p, x);
  const double d = (x - p).norm();
  const double sampled = brute_force_curve_distance(a, b, p, 2.0 * d + 0.1);
  EXPECT_LE(d, sampled + 1e-9);
  EXPECT_LT(sampled, d + 1e-2) << "the sampling must reach the nearest part of the curve";
}

} // namespace

TEST(ClosestPointOnIntersection, PlanePlaneLine)
{
  const Primitive a = make_plane({0, 0, 1}, {0, 0, 1});
  const Primitive b = make_plane({2, 0, 0}, {1, 0, 1});
  const Eigen::Vector3d p(1.7, 3.0, 1.4);
  Eigen::Vector3d x;
  ASSERT_TRUE(closest_point_on_intersection(a, b, p, 10.0, x));
  expect_on_curve_and_orthogonal(a, b, p, x);
  // The line is {z = 1, x = 1}, along y: the nearest point keeps p's y.
  EXPECT_NEAR(x.x(), 1.0, 1e-12);
  EXPECT_NEAR(x.y(), 3.0, 1e-12);
  EXPECT_NEAR(x.z(), 1.0, 1e-12);
}

TEST(ClosestPointOnIntersection, PlaneCylinderEllipse)
{
  expect_nearest_on_curve(make_plane({0, 0, 1}, {0.3, 0, 1}), make_cylinder({0, 0, 0}, {0, 0, 1}, 3.0), {3.2, 0.5, 1.4});
  expect_nearest_on_curve(make_plane({0, 0, 1}, {0.3, 0, 1}), make_cylinder({0, 0, 0}, {0, 0, 1}, 3.0), {-2.5, -1.5, 0.7});
}

TEST(ClosestPointOnIntersection, CylinderCylinder)
{
  const Primitive a = make_cylinder({0, 0, 0}, {0, 0, 1}, 3.0);
  const Primitive b = make_cylinder({0, 0, 0}, {1, 0, 0}, 2.0);
  expect_nearest_on_curve(a, b, {2.5, 1.5, 1.2});
  expect_nearest_on_curve(a, b, {-2.1, -0.2, 2.3});
}

TEST(ClosestPointOnIntersection, SpherePlaneCircle)
{
  const Primitive a = make_sphere({1, 2, 3}, 4.0);
  const Primitive b = make_plane({1, 2, 4}, {0, 0, 1});
  const Eigen::Vector3d p(3.5, 4.0, 4.6);
  Eigen::Vector3d x;
  ASSERT_TRUE(closest_point_on_intersection(a, b, p, 10.0, x));
  // Circle of centre (1, 2, 4) and radius sqrt(15) in z = 4.
  const Eigen::Vector3d c(1, 2, 4);
  Eigen::Vector3d radial = p - c;
  radial.z() = 0;
  const Eigen::Vector3d expected = c + std::sqrt(15.0) * radial.normalized();
  EXPECT_LT((x - expected).norm(), 1e-9);
  expect_nearest_on_curve(a, b, p);
}

TEST(ClosestPointOnIntersection, ConePlane)
{
  const Primitive a = make_cone({0, 0, 0}, {0, 0, 1}, kPi / 6);
  const Primitive b = make_plane({0, 0, 5}, {0, 0, 1});
  const Eigen::Vector3d p(2.5, 1.0, 5.3);
  Eigen::Vector3d x;
  ASSERT_TRUE(closest_point_on_intersection(a, b, p, 10.0, x));
  const Eigen::Vector3d expected =
      Eigen::Vector3d(0, 0, 5) + 5.0 * std::tan(kPi / 6) * Eigen::Vector3d(2.5, 1.0, 0).normalized();
  EXPECT_LT((x - expected).norm(), 1e-9);
  expect_nearest_on_curve(a, b, p);
  // An oblique section (an ellipse).
  expect_nearest_on_curve(a, make_plane({0, 0, 5}, {0.4, 0.2, 1}), {1.5, -2.0, 4.2});
}

TEST(ClosestPointOnIntersection, TorusPlane)
{
  const Primitive a = make_torus({0, 0, 0}, {0, 0, 1}, 5.0, 1.0);
  const Primitive b = make_plane({0, 0, 0.5}, {0, 0, 1});
  const Eigen::Vector3d p(6.0, 0.3, 0.7);
  Eigen::Vector3d x;
  ASSERT_TRUE(closest_point_on_intersection(a, b, p, 10.0, x));
  // The outer of the two circles, radius 5 + sqrt(1 - 0.25), is the near one.
  const Eigen::Vector3d expected =
      Eigen::Vector3d(0, 0, 0.5) + (5.0 + std::sqrt(0.75)) * Eigen::Vector3d(6.0, 0.3, 0).normalized();
  EXPECT_LT((x - expected).norm(), 1e-9);
  expect_nearest_on_curve(a, b, p);
}

TEST(ClosestPointOnIntersection, TangentOrParallelSurfacesFail)
{
  Eigen::Vector3d x(7, 7, 7);
  EXPECT_FALSE(closest_point_on_intersection(make_sphere({0, 0, 0}, 1.0), make_plane({0, 0, 1}, {0, 0, 1}),
                                             {0.05, 0.0, 1.02}, 10.0, x));
  EXPECT_FALSE(closest_point_on_intersection(make_cylinder({0, 0, 0}, {0, 0, 1}, 2.0), make_plane({2, 0, 0}, {1, 0, 0}),
                                             {2.1, 0.3, 0.5}, 10.0, x));
  EXPECT_FALSE(closest_point_on_intersection(make_plane({0, 0, 0}, {0, 0, 1}), make_plane({0, 0, 1}, {0, 0, 1}),
                                             {0.3, 0.2, 0.5}, 10.0, x));
  // Two planes 2 degrees apart: an edge exists but is too ill-conditioned to snap to.
  const double t = 2.0 * kPi / 180.0;
  EXPECT_FALSE(closest_point_on_intersection(make_plane({0, 0, 0}, {0, 0, 1}), make_plane({0, 0, 0}, {std::sin(t), 0, std::cos(t)}),
                                             {0.1, 0.2, 0.01}, 10.0, x));
  EXPECT_EQ(x, Eigen::Vector3d(7, 7, 7));
}

TEST(ClosestPointOnIntersection, FarOrInvalidInputFails)
{
  const Primitive a = make_plane({0, 0, 0}, {0, 0, 1});
  const Primitive b = make_plane({0, 0, 0}, {1, 0, 0});
  const Eigen::Vector3d p(3, 0, 0);  // 3 away from the line (the y axis)
  Eigen::Vector3d x;
  EXPECT_FALSE(closest_point_on_intersection(a, b, p, 2.0, x));
  EXPECT_TRUE(closest_point_on_intersection(a, b, p, 4.0, x));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(closest_point_on_intersection(a, b, Eigen::Vector3d(nan, 0, 0), 4.0, x));
  Primitive bad = make_sphere({0, 0, 0}, nan);
  EXPECT_FALSE(closest_point_on_intersection(a, bad, p, 4.0, x));
  EXPECT_FALSE(closest_point_on_intersection(a, b, p, nan, x));
}

TEST(CommonPointOfPrimitives, ThreePlanesExactCorner)
{
  const Primitive a = make_plane({1, 2, 3}, {1, 0.2, 0});
  const Primitive b = make_plane({-1, 0, 2}, {0.1, 1, 0.3});
  const Primitive c = make_plane({0, 0, 4}, {0.2, -0.1, 1});
  Eigen::Matrix3d n;
  n << a.axis.transpose(), b.axis.transpose(), c.axis.transpose();
  const Eigen::Vector3d d(a.axis.dot(a.origin), b.axis.dot(b.origin), c.axis.dot(c.origin));
  const Eigen::Vector3d corner = n.fullPivLu().solve(d);
  Eigen::Vector3d x;
  ASSERT_TRUE(common_point_of_primitives({&a, &b, &c}, corner + Eigen::Vector3d(0.3, -0.2, 0.25), 5.0, x));
  EXPECT_LT((x - corner).norm(), 1e-9);
}

TEST(CommonPointOfPrimitives, TwoPlanesAndCylinder)
{
  const Primitive cyl = make_cylinder({0, 0, 0}, {0, 0, 1}, 2.0);
  const Primitive top = make_plane({0, 0, 1}, {0, 0, 1});
  const Primitive side = make_plane({0, 0.5, 0}, {0, 1, 0});
  Eigen::Vector3d x;
  ASSERT_TRUE(common_point_of_primitives({&cyl, &top, &side}, {1.8, 0.6, 1.1}, 5.0, x));
  EXPECT_LT((x - Eigen::Vector3d(std::sqrt(3.75), 0.5, 1.0)).norm(), 1e-9);
  ASSERT_TRUE(common_point_of_primitives({&cyl, &top, &side}, {-1.7, 0.4, 0.9}, 5.0, x));
  EXPECT_LT((x - Eigen::Vector3d(-std::sqrt(3.75), 0.5, 1.0)).norm(), 1e-9);
}

TEST(CommonPointOfPrimitives, FourConcurrentPlanesMeetAtApex)
{
  // A square pyramid with apex (1, 2, 3).
  const Eigen::Vector3d apex(1, 2, 3);
  const Primitive a = make_plane(apex, {1, 0, 1}), b = make_plane(apex, {-1, 0, 1}), c = make_plane(apex, {0, 1, 1}),
                  d = make_plane(apex, {0, -1, 1});
  Eigen::Vector3d x;
  ASSERT_TRUE(common_point_of_primitives({&a, &b, &c, &d}, apex + Eigen::Vector3d(0.1, -0.2, -0.3), 2.0, x));
  EXPECT_LT((x - apex).norm(), 1e-9);
  // Move one face: the four planes no longer share a point.
  const Primitive d_off = make_plane(apex + Eigen::Vector3d(0, 0, 0.2), {0, -1, 1});
  EXPECT_FALSE(common_point_of_primitives({&a, &b, &c, &d_off}, apex, 2.0, x));
}

TEST(CommonPointOfPrimitives, DegenerateInputsFail)
{
  const Primitive a = make_plane({0, 0, 0}, {1, 0, 0});
  const Primitive b = make_plane({0, 0, 0}, {0, 1, 0});
  const Primitive c = make_plane({0, 0, 0}, {1, 1, 0});  // through the same line as a and b
  const Primitive z = make_plane({0, 0, 0}, {0, 0, 1});
  Eigen::Vector3d x(7, 7, 7);
  EXPECT_FALSE(common_point_of_primitives({&a, &b, &c}, {0.1, 0.1, 0.5}, 5.0, x));
  EXPECT_FALSE(common_point_of_primitives({&a, &b}, {0.1, 0.1, 0.5}, 5.0, x));
  EXPECT_FALSE(common_point_of_primitives({&a, &b, nullptr}, {0.1, 0.1, 0.5}, 5.0, x));
  EXPECT_FALSE(common_point_of_primitives({&a, &b, &z}, {3, 0, 0}, 2.0, x));  // corner too far
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(common_point_of_primitives({&a, &b, &z}, {nan, 0, 0}, 2.0, x));
  EXPECT_EQ(x, Eigen::Vector3d(7, 7, 7));
  EXPECT_TRUE(common_point_of_primitives({&a, &b, &z}, {0.5, 0.2, -0.1}, 2.0, x));
  EXPECT_LT(x.norm(), 1e-12);
}
