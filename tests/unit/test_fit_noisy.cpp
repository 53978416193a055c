// Noisy data (Gaussian, sigma = 1% of the size, fixed seeds, normals tilted ~5 degrees): radius
// within 1%, the right type from fit_primitive_auto; 10% far outliers: radius within 1% when robust.
#include "common/base/constants.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/reduce_degenerate_cone.h"
#include "common/geometry/sagitta.h"
#include "test_fit_data.h"

#include <gtest/gtest.h>

using namespace primitive_edit;
using namespace test_fit;

namespace {

struct Case
{
  const char* name;
  Primitive truth;
  Patch patch;
  double size;  // the radius whose error is checked (plane: none)
};

std::vector<Case> cases()
{
  Patch plane;
  plane.extent = 2;
  Patch cap;
  cap.cap = kPi / 3;
  Patch arc;
  arc.sweep = kPi / 2;  // a 90-degree arc: where algebraic fits are biased
  arc.extent = 4;
  Patch frustum;
  frustum.near = 2;
  frustum.far = 4;
  frustum.sweep = kPi;
  Patch quarter;
  quarter.sweep = kPi / 2;
  return {
      {"Plane", make_plane({0, 1, 2}, {0.1, 0.2, 1}), plane, 2},
      {"Sphere", make_sphere({1, -1, 0}, 2), cap, 2},
      {"Cylinder", make_cylinder({0, 0, 1}, {1, 0.2, 0.1}, 2), arc, 2},
      {"Cone", make_cone({0.5, 0, 0}, {0, 1, 0.2}, 0.45), frustum, 1.5},
      {"Torus", make_torus({0, 0, 0}, {0.2, 0, 1}, 3, 1), quarter, 1},
  };
}

double size_parameter(const Primitive& p)
{
  switch (p.type) {
  case PrimitiveType::Sphere:
  case PrimitiveType::Cylinder: return p.radius;
  case PrimitiveType::Cone: return std::tan(p.half_angle);  // radius per unit height
  case PrimitiveType::Torus: return p.minor_radius;
  case PrimitiveType::Plane: return 0;
  }
  return 0;
}

void expect_radius_within_1_percent(const Case& c, const FitResult& r)
{
  ASSERT_TRUE(r.status.ok()) << c.name << ": " << r.status.error;
  ASSERT_TRUE(primitive_is_valid(r.primitive));
  EXPECT_EQ(r.primitive.type, c.truth.type);
  if (c.truth.type == PrimitiveType::Plane) {
    EXPECT_GT(std::abs(r.primitive.axis.dot(c.truth.axis)), std::cos(0.01)) << c.name;
    return;
  }
  const double want = size_parameter(c.truth), got = size_parameter(r.primitive);
  EXPECT_LT(std::abs(got - want), 0.01 * want) << c.name << ": " << got << " vs " << want;
  if (c.truth.type == PrimitiveType::Torus) {
    EXPECT_LT(std::abs(r.primitive.radius - c.truth.radius), 0.01 * c.truth.radius) << c.name;
  }
}

TEST(FitNoisy, EachTypeRadiusWithinOnePercentAndAutoChoosesIt)
{
  unsigned seed = 10;
  for (const Case& c : cases()) {
    Sample s = sample_primitive(c.truth, c.patch, 3000, seed++);
    add_noise(&s, 0.01 * c.size, 5.0, seed++);
    for (bool with_normals : {true, false}) {
      const Eigen::MatrixX3d normals = with_normals ? s.normals : Eigen::MatrixX3d();
      SCOPED_TRACE(std::string(c.name) + (with_normals ? " with normals" : " points only"));
      expect_radius_within_1_percent(c, fit_primitive(c.truth.type, s.points, normals, Eigen::VectorXd()));
      const AutoFitResult a = fit_primitive_auto(s.points, normals, Eigen::VectorXd());
      ASSERT_TRUE(a.status.ok()) << a.status.error;
      ASSERT_EQ(a.candidates.size(), 5u);
      for (int t = 0; t < kPrimitiveTypeCount; ++t)
        if (a.candidates[static_cast<size_t>(t)].status.ok()) {
          EXPECT_EQ(a.candidates[static_cast<size_t>(t)].primitive.type, static_cast<PrimitiveType>(t));
        }
      EXPECT_EQ(a.best.primitive.type, c.truth.type)
          << "chose " << primitive_type_name(a.best.primitive.type) << " rms " << a.best.rms;
      expect_radius_within_1_percent(c, a.best);
    }
  }
}

void expect_same_fit(const FitResult& a, const FitResult& b)
{
  EXPECT_EQ(a.status.ok(), b.status.ok());
  EXPECT_EQ(a.status.error, b.status.error);
  EXPECT_EQ(a.primitive.type, b.primitive.type);
  EXPECT_EQ(a.primitive.origin, b.primitive.origin);
  EXPECT_EQ(a.primitive.axis, b.primitive.axis);
  EXPECT_EQ(a.primitive.radius, b.primitive.radius);
  EXPECT_EQ(a.primitive.minor_radius, b.primitive.minor_radius);
  EXPECT_EQ(a.primitive.half_angle, b.primitive.half_angle);
  EXPECT_EQ(a.rms, b.rms);
  EXPECT_EQ(a.point_count, b.point_count);
}

// The candidate types fitted side by side give, bit for bit, what one thread gives.
TEST(FitNoisy, SameCandidatesAndChoiceOnEveryThreadCount)
{
  unsigned seed = 60;
  for (const Case& c : cases()) {
    Sample s = sample_primitive(c.truth, c.patch, 1000, seed++);
    add_noise(&s, 0.01 * c.size, 5.0, seed++);
    const AutoFitResult one = fit_primitive_auto(s.points, s.normals, Eigen::VectorXd());
    ASSERT_TRUE(one.status.ok()) << c.name << ": " << one.status.error;
    for (int threads : {2, 3, 8}) {
      SCOPED_TRACE(std::string(c.name) + " on " + std::to_string(threads) + " threads");
      AutoFitOptions options;
      options.threads = threads;
      const AutoFitResult many = fit_primitive_auto(s.points, s.normals, Eigen::VectorXd(), options);
      EXPECT_EQ(many.status.ok(), one.status.ok());
      ASSERT_EQ(many.candidates.size(), one.candidates.size());
      for (std::size_t t = 0; t < one.candidates.size(); ++t)
        expect_same_fit(many.candidates[t], one.candidates[t]);
      expect_same_fit(many.best, one.best);
    }
  }
}

TEST(FitNoisy, TenPercentFarOutliersRejectedWhenRobust)
{
  unsigned seed = 40;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    Sample s = sample_primitive(c.truth, c.patch, 3000, seed++);
    add_noise(&s, 0.01 * c.size, 5.0, seed++);
    add_outliers(&s, 0.1, 0.5 * c.size, 2.0 * c.size, seed++);
    const FitResult r = fit_primitive(c.truth.type, s.points, s.normals, Eigen::VectorXd());
    expect_radius_within_1_percent(c, r);
    // Every point moved farther than 0.2 size from the true surface is rejected; most others are kept.
    int far = 0;
    for (Eigen::Index i = 0; i < s.points.rows(); ++i)
      far += std::abs(signed_distance_to_primitive(c.truth, s.points.row(i).transpose())) > 0.2 * c.size;
    EXPECT_GT(far, 200);
    EXPECT_LE(r.point_count, 3000 - far);
    EXPECT_GE(r.point_count, 2600);
    EXPECT_LT(r.max_residual, 0.2 * c.size);
  }
}

TEST(FitNoisy, OutliersBiasTheNonRobustFit)
{
  const Case c = cases()[1];  // sphere cap
  Sample s = sample_primitive(c.truth, c.patch, 3000, 70);
  add_outliers(&s, 0.1, 0.5 * c.size, 2.0 * c.size, 71);
  FitOptions plain;
  plain.robust = false;
  const FitResult r = fit_primitive(c.truth.type, s.points, s.normals, Eigen::VectorXd(), plain);
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  EXPECT_EQ(r.point_count, 3000);
  EXPECT_GT(r.max_residual, 0.3 * c.size);
  const FitResult robust = fit_primitive(c.truth.type, s.points, s.normals, Eigen::VectorXd());
  ASSERT_TRUE(robust.status.ok());
  EXPECT_LT(robust.rms, 1e-6 * c.size);
}

TEST(FitNoisy, RandomBlobIsFreeForm)
{
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> U(-1, 1);
  Eigen::MatrixX3d pts(2000, 3);
  for (Eigen::Index i = 0; i < pts.rows(); ++i)
    pts.row(i) << U(rng), U(rng), U(rng);
  const AutoFitResult a = fit_primitive_auto(pts, Eigen::MatrixX3d(), Eigen::VectorXd());
  EXPECT_FALSE(a.status.ok());
  EXPECT_NE(a.status.error.find("free-form"), std::string::npos) << a.status.error;
  EXPECT_EQ(a.candidates.size(), 5u);
}

TEST(FitNoisy, LargeInputIsScreenedOnASubsampleAndRefinedOnAllPoints)
{
  const Case c = cases()[2];  // cylinder arc
  Sample s = sample_primitive(c.truth, c.patch, 50000, 80);
  add_noise(&s, 0.01 * c.size, 5.0, 81);
  const AutoFitResult a = fit_primitive_auto(s.points, s.normals, Eigen::VectorXd());
  ASSERT_TRUE(a.status.ok()) << a.status.error;
  EXPECT_EQ(a.best.primitive.type, PrimitiveType::Cylinder);
  EXPECT_GT(a.best.point_count, 49000);
  EXPECT_EQ(a.candidates[2].point_count, a.best.point_count);
  EXPECT_LT(std::abs(a.best.primitive.radius - 2), 0.002 * 2);
}

// A cone refined on a noisy cylinder runs towards it (half angle to 0, apex far away) without reaching it; within
// the tolerance it is the cylinder, refined on the same points. A cone that tapers, or a tolerance finer than the
// taper, keeps the cone.
TEST(ReduceDegenerateCone, ConeThatDoesNotTaperIsItsCylinder)
{
  const Primitive truth = make_cylinder({1, 2, 0}, {0.2, 0.1, 1}, 4);
  Patch patch;
  patch.extent = 6;
  patch.sweep = kPi;
  Sample s = sample_primitive(truth, patch, 600, 11);
  add_noise(&s, 0.02, 2, 12);
  const Eigen::VectorXd weights;
  const double angle = 2e-3, apex_distance = 4 / std::tan(angle);
  FitResult near_cylinder;
  near_cylinder.primitive = make_cone(truth.origin - apex_distance * truth.axis, truth.axis, angle);
  const FitResult cone = refine_primitive(near_cylinder.primitive, s.points, weights);
  ASSERT_TRUE(cone.status.ok());
  ASSERT_EQ(cone.primitive.type, PrimitiveType::Cone);
  const double taper = axial_extent(s.points, weights, cone.primitive.axis) * std::tan(cone.primitive.half_angle);
  EXPECT_LT(taper, 0.05);

  FitOptions options;
  const FitResult reduced = reduce_degenerate_cone(cone, s.points, weights, 0.05, options);
  ASSERT_TRUE(reduced.status.ok());
  ASSERT_EQ(reduced.primitive.type, PrimitiveType::Cylinder);
  EXPECT_NEAR(reduced.primitive.radius, 4, 0.02);
  EXPECT_GT(std::abs(reduced.primitive.axis.dot(truth.axis)), std::cos(radians_from_degrees(0.5)));
  EXPECT_LT(distance_to_line(reduced.primitive.origin, truth.origin, truth.axis), 0.02);
  EXPECT_LE(reduced.rms, cone.rms * 1.01);

  const FitResult finer = reduce_degenerate_cone(cone, s.points, weights, 0.5 * taper, options);
  EXPECT_EQ(finer.primitive.type, PrimitiveType::Cone);

  Patch frustum;
  frustum.near = 2;
  frustum.far = 4;
  const Primitive tapering = make_cone({0, 0, 0}, {0, 0, 1}, radians_from_degrees(20));
  const Sample t = sample_primitive(tapering, frustum, 600, 13);
  FitResult cone_fit;
  cone_fit.primitive = tapering;
  EXPECT_EQ(reduce_degenerate_cone(cone_fit, t.points, weights, 0.05, options).primitive.type, PrimitiveType::Cone);
}

// A wide cone over an annulus (half angle 85 degrees, the points 0.5 to 1 from the apex along the axis: radii 5.7
// to 11.4) stands 0.25 off its best plane at most: within a tolerance of 0.3 it is that plane, refitted on the
// same points, within 0.2 it stays a cone. A countersink (45 degrees) is no plane at any tolerance near its size.
TEST(ReduceDegenerateCone, ConeThatDoesNotBendIsAPlane)
{
  // A cone about z with its apex at the origin, as a fit, and 600 points of it from near to far along the axis.
  auto cone_points = [](double half_angle_deg, double near, double far, unsigned seed, FitResult& cone) {
    Patch frustum;
    frustum.near = near;
    frustum.far = far;
    cone.primitive = make_cone({0, 0, 0}, {0, 0, 1}, radians_from_degrees(half_angle_deg));
    return sample_primitive(cone.primitive, frustum, 600, seed).points;
  };
  const Eigen::VectorXd weights;
  FitOptions options;
  FitResult wide;
  const Eigen::MatrixX3d annulus = cone_points(85, 0.5, 1.0, 21, wide);
  EXPECT_TRUE(cone_is_plane_within(wide.primitive, annulus, weights, 0.3));
  EXPECT_FALSE(cone_is_plane_within(wide.primitive, annulus, weights, 0.2));
  const FitResult plane = reduce_degenerate_cone(wide, annulus, weights, 0.3, options);
  ASSERT_TRUE(plane.status.ok());
  ASSERT_EQ(plane.primitive.type, PrimitiveType::Plane);
  EXPECT_GT(std::abs(plane.primitive.axis.z()), std::cos(radians_from_degrees(0.5)));
  EXPECT_NEAR(plane.primitive.origin.dot(plane.primitive.axis) * plane.primitive.axis.z(), 0.75, 0.05);
  EXPECT_EQ(reduce_degenerate_cone(wide, annulus, weights, 0.2, options).primitive.type, PrimitiveType::Cone);
  Eigen::MatrixX3d broken = annulus;
  broken(7, 1) = std::nan("");
  EXPECT_FALSE(cone_is_plane_within(wide.primitive, broken, weights, 0.3));

  FitResult sink;
  const Eigen::MatrixX3d countersink = cone_points(45, 3, 6, 22, sink);
  EXPECT_FALSE(cone_is_plane_within(sink.primitive, countersink, weights, 0.5));
  EXPECT_EQ(reduce_degenerate_cone(sink, countersink, weights, 0.5, options).primitive.type, PrimitiveType::Cone);
}

// The depth of an arc over its chord, by which the type choice and the merge call a sphere or cylinder flat: the
// 3-4-5 triangle's, none over no chord, and the radius itself once the chord spans the diameter or more.
TEST(Sagitta, ArcOverItsChord)
{
  EXPECT_DOUBLE_EQ(sagitta(5, 8), 2);
  EXPECT_DOUBLE_EQ(sagitta(5, 0), 0);
  EXPECT_DOUBLE_EQ(sagitta(5, 10), 5);
  EXPECT_DOUBLE_EQ(sagitta(5, 30), 5);
  EXPECT_NEAR(sagitta(1000, 10), 100.0 / 8000, 1e-6);  // about c^2 / 8r for a flat arc
}

} // namespace
