// Surfaces of revolution about a given axis (common/fit/fit_profile_about_axis.h) and segments refitted about a
// cylinder segment's axis (common/relate/fit_profiles_about_axes.h), on a synthetic boss: a bore of radius 4 about
// a tilted axis and the fillet round the boss's foot, a band of a torus of tube radius 1.5. A band about the axis
// gets its profile's type there; a band off the axis or tilted from it stays as fitted.
#include "common/fit/fit_primitive.h"
#include "common/fit/fit_profile_about_axis.h"
#include "common/fit/score_own_fit.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/relate/fit_profiles_about_axes.h"

#include "test_segment_samples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace {

using namespace primitive_edit;

const Eigen::Vector3d kAxisPoint(3, -2, 1);
const Eigen::Vector3d kAxis = Eigen::Vector3d(0.1, -0.2, 1).normalized();

using test_segments::max_distance;
using test_segments::revolved;

// The torus band of tube radius `tube` whose tube centre stands at (r0, h0) of the meridian, from angle a0 to a1
// (0: facing outwards, pi/2: upwards).
SegmentSamples torus_band(const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double r0, double h0,
                          double tube, double a0, double a1, int n, double sigma, unsigned seed)
{
  auto dir = [=](double u) -> Eigen::Vector2d {
    const double a = a0 + u * (a1 - a0);
    return Eigen::Vector2d(std::cos(a), std::sin(a));
  };
  return revolved(point, axis, [=](double u) -> Eigen::Vector2d { return Eigen::Vector2d(r0, h0) + tube * dir(u); }, dir, n, sigma,
                  seed);
}

SegmentSamples bore(double sigma, unsigned seed)
{
  return revolved(kAxisPoint, kAxis, [](double u) { return Eigen::Vector2d(4, 7 * u); },
                  [](double) { return Eigen::Vector2d(-1, 0); }, 3000, sigma, seed);
}

Primitive cylinder(const Eigen::Vector3d& point, const Eigen::Vector3d& axis, double radius)
{
  Primitive p;
  p.type = PrimitiveType::Cylinder;
  p.origin = point;
  p.axis = axis;
  p.radius = radius;
  return p;
}

double off_axis(const Eigen::Vector3d& x) { return test_segments::distance_from_axis(x, kAxisPoint, kAxis); }

TEST(FitProfileAboutAxis, ExactSurfacesOfRevolutionAreRecovered)
{
  struct Case
  {
    PrimitiveType type;
    SegmentSamples samples;
  };
  const std::vector<Case> cases = {
      {PrimitiveType::Cylinder, bore(0, 1)},
      // A cone opening downwards, apex at h = 12: r = (12 - h) tan 0.2 for h in [2, 8].
      {PrimitiveType::Cone,
       revolved(kAxisPoint, kAxis, [](double u) { return Eigen::Vector2d((10 - 6 * u) * std::tan(0.2), 2 + 6 * u); },
                [](double) { return Eigen::Vector2d(std::cos(0.2), std::sin(0.2)); }, 1000, 0, 2)},
      // A band of the sphere of radius 6 centred at h = 2, from h = 2 to 5.
      {PrimitiveType::Sphere, torus_band(kAxisPoint + 2 * kAxis, kAxis, 0, 0, 6, 0, std::asin(0.5), 1000, 0, 3)},
      // The quarter of the torus of tube radius 1.5 round a boss's foot.
      {PrimitiveType::Torus, torus_band(kAxisPoint, kAxis, 9.5, 1.5, 1.5, -kPi, -kPi / 2, 1000, 0, 4)},
  };
  for (const Case& c : cases) {
    const std::optional<Primitive> p = fit_profile_about_axis(c.samples.points, c.samples.weights, kAxisPoint, kAxis,
                                                              c.type);
    ASSERT_TRUE(p) << primitive_type_name(c.type);
    EXPECT_EQ(p->type, c.type);
    EXPECT_LT(max_distance(*p, c.samples), 1e-9) << primitive_type_name(c.type);
    EXPECT_LT(off_axis(p->origin), 1e-9);
    if (c.type != PrimitiveType::Sphere) {
      EXPECT_GT(std::abs(p->axis.dot(kAxis)), 1 - 1e-12);
    }
  }
  const std::optional<Primitive> torus = fit_profile_about_axis(cases[3].samples.points, cases[3].samples.weights,
                                                                kAxisPoint, kAxis, PrimitiveType::Torus);
  EXPECT_NEAR(torus->radius, 9.5, 1e-9);
  EXPECT_NEAR(torus->minor_radius, 1.5, 1e-9);
  const std::optional<Primitive> cone = fit_profile_about_axis(cases[1].samples.points, cases[1].samples.weights,
                                                               kAxisPoint, kAxis, PrimitiveType::Cone);
  EXPECT_NEAR(cone->half_angle, 0.2, 1e-9);
  EXPECT_LT((cone->origin - (kAxisPoint + 12 * kAxis)).norm(), 1e-9);
  EXPECT_LT(cone->axis.dot(kAxis), -1 + 1e-12);  // from the apex into the opening: downwards
}

TEST(FitProfileAboutAxis, RefusesWhatDoesNotFixTheType)
{
  const SegmentSamples b = bore(0, 5);
  // A cylinder's profile is a line parallel to the axis: no cone; a plane is no profile.
  EXPECT_FALSE(fit_profile_about_axis(b.points, b.weights, kAxisPoint, kAxis, PrimitiveType::Cone));
  EXPECT_FALSE(fit_profile_about_axis(b.points, b.weights, kAxisPoint, kAxis, PrimitiveType::Plane));
  // Too few points, a non-unit axis, a weight per point missing, a point at infinity.
  EXPECT_FALSE(fit_profile_about_axis(b.points.topRows(2), Eigen::VectorXd(), kAxisPoint, kAxis,
                                      PrimitiveType::Sphere));
  EXPECT_FALSE(fit_profile_about_axis(b.points, b.weights, kAxisPoint, 2 * kAxis, PrimitiveType::Cylinder));
  EXPECT_FALSE(fit_profile_about_axis(b.points, b.weights.head(10), kAxisPoint, kAxis, PrimitiveType::Cylinder));
  Eigen::MatrixX3d bad = b.points;
  bad(7, 1) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(fit_profile_about_axis(bad, b.weights, kAxisPoint, kAxis, PrimitiveType::Torus));
  EXPECT_FALSE(fit_profile_about_axis(Eigen::MatrixX3d(), Eigen::VectorXd(), kAxisPoint, kAxis,
                                      PrimitiveType::Cylinder));
}

// The bore (segment 0, its cylinder given) and a rough fillet band (segment 1) with its own fit as a sphere, the
// way a free fit types a narrow band on a rough scan.
struct Boss
{
  std::vector<SegmentSamples> samples;
  std::vector<std::optional<Primitive>> primitives;
};

Boss boss(const Eigen::Vector3d& fillet_point, const Eigen::Vector3d& fillet_axis, double sigma)
{
  Boss b;
  b.samples = {bore(sigma, 11), torus_band(fillet_point, fillet_axis, 9.5, 1.5, 1.5, -kPi, -kPi / 2, 3000, sigma, 12)};
  b.primitives = {cylinder(kAxisPoint, kAxis, 4), std::nullopt};
  const SegmentSamples& f = b.samples[1];
  FitResult sphere = fit_primitive(PrimitiveType::Sphere, f.points, f.normals, f.weights);
  EXPECT_TRUE(sphere.status.ok());
  b.primitives[1] = sphere.primitive;
  return b;
}

// The mark a blend or profile must beat: the own primitive's capped RMS and score on an evenly strided subsample.
TEST(ScoreOwnFit, ScoresTheOwnPrimitiveOnTheSubsampleAndRefusesBrokenSamples)
{
  const double tube = 1.5, sigma = 0.05;
  const SegmentSamples band = torus_band(kAxisPoint, kAxis, 8, 0, tube, 0, 0.5 * kPi, 3000, sigma, 7);
  Primitive torus;
  torus.type = PrimitiveType::Torus;
  torus.origin = kAxisPoint;
  torus.axis = kAxis;
  torus.radius = 8;
  torus.minor_radius = tube;
  const std::optional<OwnFitScore> own = score_own_fit(band, torus, 1000, 0, 0.5);
  ASSERT_TRUE(own.has_value());
  EXPECT_EQ(own->sample.points.rows(), 1000);
  EXPECT_DOUBLE_EQ(own->cap, 0.5);
  EXPECT_NEAR(own->rms, sigma, 0.2 * sigma);
  EXPECT_TRUE(std::isfinite(own->score));
  // Without a primitive the mark is the cap and any score beats it; the automatic cap follows the roughness.
  const std::optional<OwnFitScore> none = score_own_fit(band, std::nullopt, 1000, 0.1, 0);
  ASSERT_TRUE(none.has_value());
  EXPECT_GT(none->cap, 0.1);
  EXPECT_EQ(none->rms, none->cap);
  EXPECT_EQ(none->score, std::numeric_limits<double>::infinity());
  SegmentSamples broken = band;
  broken.points(3, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(score_own_fit(broken, torus, 1000, 0, 0.5).has_value());
  EXPECT_FALSE(score_own_fit(SegmentSamples(), torus, 1000, 0, 0.5).has_value());
  SegmentSamples weightless = band;
  weightless.weights.setZero();
  EXPECT_FALSE(score_own_fit(weightless, torus, 1000, 0, 0.5).has_value());
  const std::optional<OwnFitScore> unknown_roughness = score_own_fit(band, torus, 1000, 0, 0);
  ASSERT_TRUE(unknown_roughness.has_value()); // the automatic cap: 1% of the extent
  EXPECT_DOUBLE_EQ(unknown_roughness->cap, 0.01 * unknown_roughness->diagonal);
}

TEST(FitProfilesAboutAxes, AFilletBandAboutTheBoreIsItsTorus)
{
  const Boss b = boss(kAxisPoint, kAxis, 0.1);
  const std::vector<SegmentProfile> profiles =
      fit_profiles_about_axes(b.primitives, b.samples, 0.1, 0, 10, 0.3);
  ASSERT_EQ(profiles.size(), 1u);
  const SegmentProfile& q = profiles[0];
  EXPECT_EQ(q.segment, 1);
  EXPECT_EQ(q.axis_segment, 0);
  ASSERT_EQ(q.primitive.type, PrimitiveType::Torus);
  EXPECT_NEAR(q.primitive.radius, 9.5, 0.1);
  EXPECT_NEAR(q.primitive.minor_radius, 1.5, 0.1);
  EXPECT_GT(std::abs(q.primitive.axis.dot(kAxis)), 1 - 1e-12);
  EXPECT_LT(off_axis(q.primitive.origin), 1e-9);
  EXPECT_LT(q.rms, 0.12);
}

TEST(FitProfilesAboutAxes, ABandOffTheAxisOrTiltedStaysAsFitted)
{
  // 2 mm beside the bore's axis, with the relations' distance 0.3 (3 x the noise).
  const Eigen::Vector3d beside = kAxisPoint + 2 * kAxis.unitOrthogonal();
  const Boss b = boss(beside, kAxis, 0.1);
  EXPECT_TRUE(fit_profiles_about_axes(b.primitives, b.samples, 0.1, 0, 10, 0.3).empty());
  // Tilted 20 degrees from it, beyond the relations' 10.
  const Eigen::Vector3d tilted =
      Eigen::AngleAxisd(radians_from_degrees(20), kAxis.unitOrthogonal()) * kAxis;
  const Boss t = boss(kAxisPoint, tilted, 0.1);
  EXPECT_TRUE(fit_profiles_about_axes(t.primitives, t.samples, 0.1, 0, 10, 0.3).empty());
  // On the axis, but the distance asked is below the own sphere's offset from it.
  const Boss on = boss(kAxisPoint, kAxis, 0.1);
  const double offset = off_axis(on.primitives[1]->origin);
  EXPECT_GT(offset, 1e-3);
  EXPECT_TRUE(fit_profiles_about_axes(on.primitives, on.samples, 0.1, 0, 10, 0.5 * offset).empty());
  EXPECT_EQ(fit_profiles_about_axes(on.primitives, on.samples, 0.1, 0, 10, 2 * offset).size(), 1u);
}

TEST(FitProfilesAboutAxes, TheTypeAskedIsKeptAndAnExactTorusStaysExact)
{
  const Boss rough = boss(kAxisPoint, kAxis, 0.1);
  // Asked to be a sphere, the band can only become the sphere about the axis.
  for (const SegmentProfile& q : fit_profiles_about_axes(rough.primitives, rough.samples, 0.1, 0, 10, 0.3,
                                                         {std::nullopt, PrimitiveType::Sphere}))
    EXPECT_EQ(q.primitive.type, PrimitiveType::Sphere);
  // Asked to be a plane (or given no primitive): nothing to do.
  EXPECT_TRUE(fit_profiles_about_axes(rough.primitives, rough.samples, 0.1, 0, 10, 0.3,
                                      {std::nullopt, PrimitiveType::Plane})
                  .empty());
  Boss exact = boss(kAxisPoint, kAxis, 0);
  Primitive torus;
  torus.type = PrimitiveType::Torus;
  torus.origin = kAxisPoint + 1.5 * kAxis;
  torus.axis = kAxis;
  torus.radius = 9.5;
  torus.minor_radius = 1.5;
  exact.primitives[1] = torus;
  for (const SegmentProfile& q : fit_profiles_about_axes(exact.primitives, exact.samples, 0, 0, 10, 0.3))
    EXPECT_LT(max_distance(q.primitive, exact.samples[1]), 1e-9);
}

// On a rough scan (noise 0.2, the tolerance 3 x that) a band of a boss fits a sphere about the axis a little better
// than a cone, as the bracket scan's boss did; but its arc sags 0.38 over the band, less than the tolerance, which
// is no evidence of a sphere, so the band is the cone of its chord. A band of a sphere whose arc sags 0.8 over it
// stays a sphere.
TEST(FitProfilesAboutAxes, ASphereThatSagsLessThanTheToleranceIsTheConeOfItsChord)
{
  const double sigma = 0.2;
  auto profiles_of = [&](const SegmentSamples& band) {
    Boss b;
    b.samples = {bore(sigma, 21), band};
    b.primitives = {cylinder(kAxisPoint, kAxis, 4), std::nullopt};
    const FitResult sphere = fit_primitive(PrimitiveType::Sphere, band.points, band.normals, band.weights);
    EXPECT_TRUE(sphere.status.ok());
    b.primitives[1] = sphere.primitive;
    return fit_profiles_about_axes(b.primitives, b.samples, sigma, 0, 10, 3 * sigma);
  };
  // The sphere of radius 8.5 about the axis from h = -2.5 to 2.5: r from 8.12 to 8.5.
  const double a = std::asin(2.5 / 8.5);
  const std::vector<SegmentProfile> flat =
      profiles_of(torus_band(kAxisPoint, kAxis, 0, 0, 8.5, -a, a, 3000, sigma, 22));
  ASSERT_EQ(flat.size(), 1u);
  EXPECT_EQ(flat[0].primitive.type, PrimitiveType::Cone);
  // The sphere of radius 6 about the axis from its equator up 60 degrees: r from 6 to 3 over h from 0 to 5.2.
  const std::vector<SegmentProfile> round =
      profiles_of(torus_band(kAxisPoint + 2 * kAxis, kAxis, 0, 0, 6, 0, kPi / 3, 3000, sigma, 23));
  ASSERT_EQ(round.size(), 1u);
  EXPECT_EQ(round[0].primitive.type, PrimitiveType::Sphere);
}

TEST(FitProfilesAboutAxes, BrokenInputGivesNothing)
{
  Boss b = boss(kAxisPoint, kAxis, 0.1);
  b.samples[1].points(5, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(fit_profiles_about_axes(b.primitives, b.samples, 0.1, 0, 10, 0.3).empty());
  const Boss good = boss(kAxisPoint, kAxis, 0.1);
  EXPECT_TRUE(fit_profiles_about_axes(good.primitives, good.samples, 0.1, 0, 10, 0).empty());    // no distance
  EXPECT_TRUE(fit_profiles_about_axes(good.primitives, good.samples, 0.1, 0, 90, 0.3).empty());  // angle out of range
  EXPECT_TRUE(fit_profiles_about_axes(good.primitives, {}, 0.1, 0, 10, 0.3).empty());
  Boss no_bore = boss(kAxisPoint, kAxis, 0.1);
  no_bore.primitives[0] = std::nullopt;
  EXPECT_TRUE(fit_profiles_about_axes(no_bore.primitives, no_bore.samples, 0.1, 0, 10, 0.3).empty());
}

} // namespace
