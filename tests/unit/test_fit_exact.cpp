// Exact (noise-free) samples of every primitive type, full and partial patches, with and without
// normals: each fit must recover the parameters to 1e-5 relative error, in the output conventions.
#include "common/base/constants.h"
#include "common/fit/fit_primitive.h"
#include "test_fit_data.h"

#include <gtest/gtest.h>

using namespace primitive_edit;
using namespace test_fit;

namespace {

constexpr double kTol = 1e-5;

FitResult fit(const Primitive& truth, const Sample& s, bool with_normals)
{
  const Eigen::MatrixX3d none;
  return fit_primitive(truth.type, s.points, with_normals ? s.normals : none, Eigen::VectorXd());
}

void expect_parallel(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  EXPECT_GT(std::abs(a.normalized().dot(b.normalized())), 1 - 1e-10) << a.transpose() << " vs " << b.transpose();
}

void expect_fit_quality(const FitResult& r, const Sample& s, double size)
{
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  EXPECT_TRUE(primitive_is_valid(r.primitive));
  EXPECT_LT(r.rms, kTol * size);
  EXPECT_LT(r.max_residual, kTol * size);
  EXPECT_EQ(r.point_count, s.points.rows());
}

class ExactFit : public ::testing::TestWithParam<bool> {};

TEST_P(ExactFit, PlaneRecovered)
{
  const Primitive truth = make_plane({1, -2, 0.5}, {0.3, -0.2, 0.9});
  Patch patch;
  patch.extent = 2;
  const Sample s = sample_primitive(truth, patch, 400, 1);
  const FitResult r = fit(truth, s, GetParam());
  expect_fit_quality(r, s, 2);
  expect_parallel(r.primitive.axis, truth.axis);
  EXPECT_NEAR((r.primitive.origin - truth.origin).dot(truth.axis), 0, kTol);
}

TEST_P(ExactFit, SphereFullAndCap)
{
  const Primitive truth = make_sphere({0.5, 2, -1}, 3);
  for (double cap : {kPi, kPi / 4}) {
    Patch patch;
    patch.cap = cap;
    const Sample s = sample_primitive(truth, patch, 500, 2);
    const FitResult r = fit(truth, s, GetParam());
    expect_fit_quality(r, s, 3);
    EXPECT_LT((r.primitive.origin - truth.origin).norm(), kTol * 3) << "cap " << cap;
    EXPECT_NEAR(r.primitive.radius, 3, kTol * 3) << "cap " << cap;
  }
}

TEST_P(ExactFit, CylinderFullAnd60DegreeArc)
{
  const Primitive truth = make_cylinder({1, 1, 1}, {1, 2, -0.5}, 2);
  for (double sweep : {2 * kPi, kPi / 3}) {
    Patch patch;
    patch.sweep = sweep;
    patch.extent = 3;
    const Sample s = sample_primitive(truth, patch, 500, 3);
    const FitResult r = fit(truth, s, GetParam());
    expect_fit_quality(r, s, 2);
    expect_parallel(r.primitive.axis, truth.axis);
    EXPECT_LT(distance_to_line(truth.origin, r.primitive.origin, r.primitive.axis), kTol * 2) << "sweep " << sweep;
    EXPECT_NEAR(r.primitive.radius, 2, kTol * 2) << "sweep " << sweep;
  }
}

TEST_P(ExactFit, ConeFullAndShortFrustumSector)
{
  const Primitive truth = make_cone({-1, 0.5, 2}, {0.2, -1, 0.4}, 0.5);
  Patch full;
  full.near = 0.5;
  full.far = 2.5;
  Patch frustum;  // short frustum, a third of the way around
  frustum.near = 2.0;
  frustum.far = 2.6;
  frustum.sweep = 2 * kPi / 3;
  for (const Patch& patch : {full, frustum}) {
    const Sample s = sample_primitive(truth, patch, 500, 4);
    const FitResult r = fit(truth, s, GetParam());
    expect_fit_quality(r, s, 1);
    EXPECT_GT(r.primitive.axis.dot(truth.axis), 1 - 1e-10) << "axis must point from apex into the opening";
    EXPECT_LT((r.primitive.origin - truth.origin).norm(), kTol * 2);
    EXPECT_NEAR(r.primitive.half_angle, 0.5, kTol);
  }
}

TEST_P(ExactFit, TorusFullAndQuarter)
{
  const Primitive truth = make_torus({2, -1, 0}, {0.1, 0.3, 1}, 3, 0.8);
  for (double sweep : {2 * kPi, kPi / 2}) {
    Patch patch;
    patch.sweep = sweep;
    const Sample s = sample_primitive(truth, patch, 800, 5);
    const FitResult r = fit(truth, s, GetParam());
    expect_fit_quality(r, s, 3);
    expect_parallel(r.primitive.axis, truth.axis);
    EXPECT_LT((r.primitive.origin - truth.origin).norm(), kTol * 3) << "sweep " << sweep;
    EXPECT_NEAR(r.primitive.radius, 3, kTol * 3) << "sweep " << sweep;
    EXPECT_NEAR(r.primitive.minor_radius, 0.8, kTol * 0.8) << "sweep " << sweep;
  }
}

INSTANTIATE_TEST_SUITE_P(WithAndWithoutNormals, ExactFit, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "WithNormals" : "PointsOnly";
                         });

} // namespace
