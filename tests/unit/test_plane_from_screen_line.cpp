// Tests of common/geometry/plane_from_screen_line.h (the split tool's cutting plane) and common/geometry/primitive_wireframe.h
// (the drawing of a fitted primitive).
#include "common/base/constants.h"
#include "common/geometry/plane_from_screen_line.h"
#include "common/geometry/primitive_wireframe.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace {

using namespace primitive_edit;


Eigen::Matrix4d perspective(double fovy, double aspect, double n, double f)
{
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  const double t = 1 / std::tan(fovy / 2);
  p(0, 0) = t / aspect;
  p(1, 1) = t;
  p(2, 2) = (f + n) / (n - f);
  p(2, 3) = 2 * f * n / (n - f);
  p(3, 2) = -1;
  return p;
}

Eigen::Matrix4d orthographic(double half_width, double half_height, double n, double f)
{
  Eigen::Matrix4d p = Eigen::Matrix4d::Identity();
  p(0, 0) = 1 / half_width;
  p(1, 1) = 1 / half_height;
  p(2, 2) = -2 / (f - n);
  p(2, 3) = -(f + n) / (f - n);
  return p;
}

// Window coordinates of an object point.
Eigen::Vector3d project(const Eigen::Vector3d& x, const Eigen::Matrix4d& mv, const Eigen::Matrix4d& pr,
                        const Eigen::Vector4d& vp)
{
  const Eigen::Vector4d c = pr * mv * x.homogeneous();
  return Eigen::Vector3d(vp[0] + vp[2] * (c.x() / c.w() + 1) / 2, vp[1] + vp[3] * (c.y() / c.w() + 1) / 2,
                         c.z() / c.w());
}

// A camera turned and moved arbitrarily, so that object and eye coordinates differ.
Eigen::Matrix4d some_modelview()
{
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(Eigen::Vector3d(0.3, -0.2, -15));
  t.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 0.5).normalized()));
  t.translate(Eigen::Vector3d(-1, 2, 0.5));
  return t.matrix();
}

void expect_plane_contains_screen_line(const Eigen::Matrix4d& mv, const Eigen::Matrix4d& pr)
{
  const Eigen::Vector4d vp(10, 20, 640, 480);
  const Eigen::Vector2d a(100, 300), b(500, 150);
  const ScreenLinePlane plane = plane_from_screen_line(a, b, mv, pr, vp);
  ASSERT_TRUE(plane.status.ok()) << plane.status.error;
  EXPECT_NEAR(plane.normal.norm(), 1.0, 1e-12);
  // Points that project onto the line, at any depth, lie on the plane; points off the line do not, and
  // the side of the plane follows the side of the line on screen.
  const Eigen::Matrix4d inverse = (pr * mv).inverse();
  const Eigen::Vector2d across = Eigen::Vector2d(-(b - a).y(), (b - a).x()).normalized();
  double first_side = 0.0;
  for (double t : {-0.5, 0.0, 0.3, 1.0, 2.0})
    for (double depth : {-0.9, 0.0, 0.95})
      for (double offset : {0.0, 25.0, -25.0}) {
        const Eigen::Vector2d w = a + t * (b - a) + offset * across;
        const Eigen::Vector4d ndc(2 * (w.x() - vp[0]) / vp[2] - 1, 2 * (w.y() - vp[1]) / vp[3] - 1, depth, 1);
        const Eigen::Vector4d h = inverse * ndc;
        const Eigen::Vector3d x = h.head<3>() / h.w();
        ASSERT_NEAR((project(x, mv, pr, vp).head<2>() - w).norm(), 0.0, 1e-6);
        const double distance = (x - plane.point).dot(plane.normal);
        if (offset == 0.0) {
          EXPECT_NEAR(distance, 0.0, 1e-9 * (1 + x.norm()));
          continue;
        }
        // One screen side of the line is one side of the plane, whatever the depth.
        const double side = distance * offset;
        EXPECT_GT(std::abs(distance), 1e-6);
        if (first_side == 0.0)
          first_side = side;
        EXPECT_GT(side * first_side, 0.0) << "t " << t << " depth " << depth << " offset " << offset;
      }
}

TEST(PlaneFromScreenLine, PerspectiveCamera)
{
  expect_plane_contains_screen_line(some_modelview(), perspective(kPi / 3, 4.0 / 3, 0.1, 100));
}

TEST(PlaneFromScreenLine, OrthographicCamera)
{
  expect_plane_contains_screen_line(some_modelview(), orthographic(8, 6, 0.1, 100));
}

TEST(PlaneFromScreenLine, HorizontalLineThroughCentreIsTheHorizontalPlane)
{
  Eigen::Matrix4d mv = Eigen::Matrix4d::Identity();
  mv(2, 3) = -20;
  const ScreenLinePlane plane =
      plane_from_screen_line({0, 400}, {800, 400}, mv, perspective(kPi / 3, 1, 1, 100), {0, 0, 800, 800});
  ASSERT_TRUE(plane.status.ok());
  EXPECT_NEAR(std::abs(plane.normal.y()), 1.0, 1e-12);
  EXPECT_NEAR(plane.point.y(), 0.0, 1e-9);
}

TEST(PlaneFromScreenLine, RefusesDegenerateInput)
{
  const Eigen::Matrix4d mv = some_modelview(), pr = perspective(kPi / 3, 1, 1, 100);
  const Eigen::Vector4d vp(0, 0, 800, 800);
  EXPECT_FALSE(plane_from_screen_line({5, 5}, {5, 5}, mv, pr, vp).status.ok());
  EXPECT_FALSE(plane_from_screen_line({NAN, 5}, {5, 7}, mv, pr, vp).status.ok());
  EXPECT_FALSE(plane_from_screen_line({1, 5}, {5, 7}, mv, pr, {0, 0, 0, 800}).status.ok());
  EXPECT_FALSE(plane_from_screen_line({1, 5}, {5, 7}, Eigen::Matrix4d::Zero(), pr, vp).status.ok());
  Eigen::Matrix4d inf = mv;
  inf(0, 0) = std::numeric_limits<double>::infinity();
  const ScreenLinePlane bad = plane_from_screen_line({1, 5}, {5, 7}, inf, pr, vp);
  EXPECT_FALSE(bad.status.ok());
  EXPECT_FALSE(bad.status.error.empty());
}

// Every line end of the wireframe lies on the primitive.
void expect_on_surface(const Primitive& p, const Eigen::MatrixX3d& points)
{
  const Eigen::MatrixX3d lines = primitive_wireframe(p, points);
  ASSERT_GT(lines.rows(), 0);
  ASSERT_EQ(lines.rows() % 2, 0);
  for (Eigen::Index i = 0; i < lines.rows(); ++i)
    ASSERT_NEAR(project_onto_primitive(p, lines.row(i).transpose()).signed_distance, 0.0, 1e-9) << i;
}

TEST(PrimitiveWireframe, LiesOnEveryTypeAndSpansThePoints)
{
  Eigen::MatrixX3d points(4, 3);
  points << 1, 0, -2, 0, 1, 3, -1, 0, 1, 0, -1, 0.5;
  Primitive p;
  p.type = PrimitiveType::Plane;
  p.axis = Eigen::Vector3d(0, 0.6, 0.8);
  expect_on_surface(p, points);
  p.type = PrimitiveType::Sphere;
  p.radius = 2;
  expect_on_surface(p, points);
  p.type = PrimitiveType::Cylinder;
  p.axis = Eigen::Vector3d::UnitZ();
  expect_on_surface(p, points);
  // The cylinder's lines run over the points' axial extent, z in [-2, 3].
  const Eigen::MatrixX3d lines = primitive_wireframe(p, points);
  EXPECT_NEAR(lines.col(2).minCoeff(), -2.0, 1e-12);
  EXPECT_NEAR(lines.col(2).maxCoeff(), 3.0, 1e-12);
  p.type = PrimitiveType::Cone;
  p.half_angle = 0.4;
  expect_on_surface(p, points);
  p.type = PrimitiveType::Torus;
  p.radius = 3;
  p.minor_radius = 1;
  expect_on_surface(p, points);
  expect_on_surface(p, Eigen::MatrixX3d(0, 3));
}

TEST(PrimitiveWireframe, InvalidPrimitiveDrawsNothing)
{
  Primitive p;
  p.type = PrimitiveType::Cylinder;
  p.radius = std::nan("");
  EXPECT_EQ(primitive_wireframe(p, Eigen::MatrixX3d(0, 3)).rows(), 0);
}

} // namespace
