// Bad input to the fits (too few points, NaN/Inf, mismatched sizes, negative weights, degenerate
// point sets) and the output conventions (plane normal along the normals, cylinder origin nearest the
// centroid, cone axis into the opening, weights honoured).
#include "common/base/constants.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/refine_primitive.h"
#include "test_fit_data.h"

#include <gtest/gtest.h>

#include <limits>

using namespace primitive_edit;
using namespace test_fit;

namespace {

const PrimitiveType kTypes[] = {PrimitiveType::Plane, PrimitiveType::Sphere, PrimitiveType::Cylinder,
                                PrimitiveType::Cone, PrimitiveType::Torus};

Sample cylinder_sample(int n)
{
  Patch patch;
  patch.extent = 2;
  return sample_primitive(make_cylinder({0, 0, 0}, {0, 0, 1}, 1), patch, n, 5);
}

TEST(FitInput, TooFewPointsRejectedWithMessage)
{
  for (PrimitiveType t : kTypes) {
    const Sample s = cylinder_sample(minimum_points_for(t) - 1);
    const FitResult r = fit_primitive(t, s.points, s.normals, Eigen::VectorXd());
    EXPECT_FALSE(r.status.ok()) << primitive_type_name(t);
    EXPECT_NE(r.status.error.find("too few points"), std::string::npos) << r.status.error;
  }
  const AutoFitResult a = fit_primitive_auto(Eigen::MatrixX3d(), Eigen::MatrixX3d(), Eigen::VectorXd());
  EXPECT_FALSE(a.status.ok());
  EXPECT_FALSE(a.status.error.empty());
}

TEST(FitInput, ZeroWeightsDoNotCountAsPoints)
{
  const Sample s = cylinder_sample(50);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(50);
  w.head(4).setOnes();
  EXPECT_FALSE(fit_cylinder(s.points, s.normals, w).status.ok());
  w.head(20).setOnes();
  const FitResult r = fit_cylinder(s.points, s.normals, w);
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  EXPECT_EQ(r.point_count, 20);
}

TEST(FitInput, NonFiniteValuesRejected)
{
  for (PrimitiveType t : kTypes) {
    Sample s = cylinder_sample(100);
    s.points(17, 1) = std::numeric_limits<double>::quiet_NaN();
    FitResult r = fit_primitive(t, s.points, s.normals, Eigen::VectorXd());
    EXPECT_FALSE(r.status.ok());
    EXPECT_NE(r.status.error.find("non-finite"), std::string::npos) << r.status.error;
    s = cylinder_sample(100);
    s.normals(3, 0) = std::numeric_limits<double>::infinity();
    r = fit_primitive(t, s.points, s.normals, Eigen::VectorXd());
    EXPECT_FALSE(r.status.ok());
    EXPECT_NE(r.status.error.find("non-finite"), std::string::npos) << r.status.error;
    Eigen::VectorXd w = Eigen::VectorXd::Ones(100);
    w[5] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(fit_primitive(t, cylinder_sample(100).points, Eigen::MatrixX3d(), w).status.ok());
  }
}

// Found by fuzz/fuzz_fit.cpp: the refinement alone (the edit tool's and the fits' last step) took NaN points and
// reported success with a NaN residual.
TEST(FitInput, RefinementRejectsNonFinitePointsAndWeights)
{
  const Sample s = cylinder_sample(100);
  const FitResult fit = fit_primitive(PrimitiveType::Cylinder, s.points, s.normals, Eigen::VectorXd());
  ASSERT_TRUE(fit.status.ok());
  EXPECT_TRUE(refine_primitive(fit.primitive, s.points, Eigen::VectorXd()).status.ok());
  Eigen::MatrixX3d points = s.points;
  points(17, 1) = std::numeric_limits<double>::quiet_NaN();
  FitResult r = refine_primitive(fit.primitive, points, Eigen::VectorXd());
  EXPECT_FALSE(r.status.ok());
  EXPECT_NE(r.status.error.find("non-finite"), std::string::npos) << r.status.error;
  Eigen::VectorXd w = Eigen::VectorXd::Ones(100);
  w[5] = -1;
  EXPECT_FALSE(refine_primitive(fit.primitive, s.points, w).status.ok());
}

TEST(FitInput, MismatchedSizesAndNegativeWeightsRejected)
{
  const Sample s = cylinder_sample(100);
  const Eigen::MatrixX3d short_normals = s.normals.topRows(50);
  for (PrimitiveType t : kTypes) {
    FitResult r = fit_primitive(t, s.points, short_normals, Eigen::VectorXd());
    EXPECT_FALSE(r.status.ok());
    EXPECT_NE(r.status.error.find("normals"), std::string::npos) << r.status.error;
    r = fit_primitive(t, s.points, s.normals, Eigen::VectorXd::Ones(99));
    EXPECT_FALSE(r.status.ok());
    EXPECT_NE(r.status.error.find("weights"), std::string::npos) << r.status.error;
    Eigen::VectorXd w = Eigen::VectorXd::Ones(100);
    w[7] = -1;
    r = fit_primitive(t, s.points, s.normals, w);
    EXPECT_FALSE(r.status.ok());
    EXPECT_NE(r.status.error.find("non-negative"), std::string::npos) << r.status.error;
  }
}

TEST(FitInput, CoplanarPointsGiveNoSphere)
{
  Patch patch;
  const Sample s = sample_primitive(make_plane({1, 2, 3}, {0, 1, 1}), patch, 300, 9);
  for (bool with_normals : {true, false}) {
    const FitResult r = fit_sphere(s.points, with_normals ? s.normals : Eigen::MatrixX3d(), Eigen::VectorXd());
    if (r.status.ok())
      ADD_FAILURE() << "sphere of radius " << r.primitive.radius << " on coplanar points";
    EXPECT_FALSE(r.status.error.empty());
  }
  const AutoFitResult a = fit_primitive_auto(s.points, s.normals, Eigen::VectorXd());
  ASSERT_TRUE(a.status.ok()) << a.status.error;
  EXPECT_EQ(a.best.primitive.type, PrimitiveType::Plane);
}

TEST(FitInput, CoincidentOrCollinearPointsNeverGiveNaN)
{
  Eigen::MatrixX3d same = Eigen::MatrixX3d::Constant(40, 3, 2.5);
  Eigen::MatrixX3d line(40, 3);
  for (int i = 0; i < 40; ++i)
    line.row(i) << i, 2.0 * i, -1.0 * i;
  for (const Eigen::MatrixX3d* pts : {&same, &line})
    for (PrimitiveType t : kTypes) {
      const FitResult r = fit_primitive(t, *pts, Eigen::MatrixX3d(), Eigen::VectorXd());
      if (r.status.ok()) {
        EXPECT_TRUE(primitive_is_valid(r.primitive)) << primitive_type_name(t);
        EXPECT_TRUE(std::isfinite(r.rms));
      } else {
        EXPECT_FALSE(r.status.error.empty()) << primitive_type_name(t);
      }
    }
  EXPECT_FALSE(fit_plane(line, Eigen::MatrixX3d(), Eigen::VectorXd()).status.ok());
  EXPECT_FALSE(fit_primitive_auto(same, Eigen::MatrixX3d(), Eigen::VectorXd()).status.ok());
}

TEST(FitConventions, PlaneNormalFollowsGivenNormalsAndOriginIsProjectedCentroid)
{
  Patch patch;
  for (double sign : {1.0, -1.0}) {
    const Sample s = sample_primitive(make_plane({0, 0, 1}, sign * Eigen::Vector3d(0.2, 0.1, 1)), patch, 200, 3);
    const FitResult r = fit_plane(s.points, s.normals, Eigen::VectorXd());
    ASSERT_TRUE(r.status.ok());
    EXPECT_GT(r.primitive.axis.dot(s.normals.row(0).transpose()), 0.999);
    const Eigen::Vector3d centroid = s.points.colwise().mean().transpose();
    EXPECT_LT((r.primitive.origin - centroid).norm(), 1e-9);
  }
}

TEST(FitConventions, CylinderOriginIsAxisPointNearestTheCentroid)
{
  Patch patch;
  patch.sweep = kPi / 2;
  patch.extent = 2;
  const Sample s = sample_primitive(make_cylinder({1, 2, 3}, {0, 1, 1}, 1.5), patch, 300, 4);
  const FitResult r = fit_cylinder(s.points, s.normals, Eigen::VectorXd());
  ASSERT_TRUE(r.status.ok());
  const Eigen::Vector3d centroid = s.points.colwise().mean().transpose();
  EXPECT_NEAR((centroid - r.primitive.origin).dot(r.primitive.axis), 0, 1e-9);
  EXPECT_NEAR(r.primitive.axis.norm(), 1, 1e-12);
}

TEST(FitConventions, ConeAxisPointsIntoTheOpeningEitherWay)
{
  Patch patch;
  patch.near = 1;
  patch.far = 3;
  for (double sign : {1.0, -1.0}) {
    const Primitive truth = make_cone({0, 0, 0}, sign * Eigen::Vector3d(0.3, 0.2, 1), 0.3);
    Sample s = sample_primitive(truth, patch, 400, 6);
    // Inward normals must not flip the axis either.
    const Sample inward{s.points, -s.normals};
    for (const Sample* data : std::initializer_list<const Sample*>{&s, &inward}) {
      const FitResult r = fit_cone(data->points, data->normals, Eigen::VectorXd());
      ASSERT_TRUE(r.status.ok());
      EXPECT_GT(r.primitive.axis.dot(truth.axis), 1 - 1e-9);
      EXPECT_GT(r.primitive.half_angle, 0);
      EXPECT_LT(r.primitive.half_angle, kPi / 2);
      EXPECT_NEAR(r.primitive.half_angle, 0.3, 1e-7);
    }
  }
}

TEST(FitConventions, WeightsSelectThePointsThatCount)
{
  // Two parallel planes: the weights decide which one is fitted.
  Patch patch;
  Sample a = sample_primitive(make_plane({0, 0, 0}, {0, 0, 1}), patch, 100, 1);
  Sample b = sample_primitive(make_plane({0, 0, 1}, {0, 0, 1}), patch, 100, 2);
  Eigen::MatrixX3d pts(200, 3);
  pts << a.points, b.points;
  Eigen::VectorXd w = Eigen::VectorXd::Zero(200);
  w.tail(100).setConstant(0.25);
  FitOptions plain;
  plain.robust = false;
  const FitResult r = fit_plane(pts, Eigen::MatrixX3d(), w, plain);
  ASSERT_TRUE(r.status.ok());
  EXPECT_NEAR(r.primitive.origin.z(), 1, 1e-12);
  EXPECT_EQ(r.point_count, 100);
}

} // namespace
