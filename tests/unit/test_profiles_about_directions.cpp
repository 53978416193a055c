// Surfaces of revolution about a given direction, the axis placed by the fit
// (common/fit/fit_profile_about_direction.h), and curved segments refitted about the part's directions
// (common/relate/fit_profiles_about_directions.h), on the bracket's short hole: a band of a cylinder of radius 2.75
// and height 2.75 through a plate whose normal is the part's direction. On a rough scan its own fit tilts; about the
// direction it is its cylinder. A hole tilted from every direction stays as fitted.
#include "common/fit/fit_primitive.h"
#include "common/fit/fit_profile_about_direction.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/relate/fit_profiles_about_directions.h"

#include "test_segment_samples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

// Named: the unit tests build in batches (UNITY_BUILD), beside the profiles about an axis and their helpers.
namespace profiles_about_directions_test {

using namespace primitive_edit;

const Eigen::Vector3d kAxisPoint(10, 12.5, 0);
const Eigen::Vector3d kDirection = Eigen::Vector3d(0.05, -0.1, 1).normalized();

using test_segments::max_distance;
using test_segments::revolved;

SegmentSamples hole(const Eigen::Vector3d& axis, double sigma, unsigned seed, int n = 1500)
{
  return revolved(kAxisPoint, axis, [](double u) { return Eigen::Vector2d(2.75, 2.25 + 2.75 * u); },
                  [](double) { return Eigen::Vector2d(-1, 0); }, n, sigma, seed);
}

// A corner's quarter round: the quarter turn of a torus of tube radius 1.5 at major radius 3.5.
SegmentSamples corner_round(double sigma, unsigned seed)
{
  const auto out = [](double u) { return Eigen::Vector2d(std::cos(0.5 * kPi * u), std::sin(0.5 * kPi * u)); };
  const auto profile = [out](double u) -> Eigen::Vector2d { return Eigen::Vector2d(3.5, 0) + 1.5 * out(u); };
  return revolved(kAxisPoint, kDirection, profile, out, 800, sigma, seed, 1, 0.25);
}

double off_axis(const Eigen::Vector3d& x) { return test_segments::distance_from_axis(x, kAxisPoint, kDirection); }

TEST(FitProfileAboutDirection, ExactSurfacesAreRecoveredWithTheirAxisPlaced)
{
  struct Case
  {
    PrimitiveType type;
    SegmentSamples samples;
  };
  const std::vector<Case> cases = {
      {PrimitiveType::Cylinder, hole(kDirection, 0, 1)},
      // The countersink under the hole: a 45-degree cone, apex on the axis at h = 0.
      {PrimitiveType::Cone,
       revolved(kAxisPoint, kDirection, [](double u) { return Eigen::Vector2d(2.75 + 1.25 * u, 2.75 - 1.25 * u); },
                [](double) { return Eigen::Vector2d(std::sqrt(0.5), -std::sqrt(0.5)); }, 1000, 0, 2)},
      {PrimitiveType::Torus, corner_round(0, 3)},
  };
  for (const Case& c : cases) {
    const std::optional<Primitive> p =
        fit_profile_about_direction(c.samples.points, c.samples.weights, kDirection, c.type);
    ASSERT_TRUE(p) << primitive_type_name(c.type);
    EXPECT_EQ(p->type, c.type);
    EXPECT_LT(max_distance(*p, c.samples), 1e-6) << primitive_type_name(c.type);
    EXPECT_LT(off_axis(p->origin), 1e-6) << primitive_type_name(c.type);
    EXPECT_GT(std::abs(p->axis.dot(kDirection)), 1 - 1e-12);
  }
  const std::optional<Primitive> torus =
      fit_profile_about_direction(cases[2].samples.points, cases[2].samples.weights, kDirection, PrimitiveType::Torus);
  EXPECT_NEAR(torus->radius, 3.5, 1e-6);
  EXPECT_NEAR(torus->minor_radius, 1.5, 1e-6);
  // A plane about a direction is the one of that normal through the points' mean.
  const SegmentSamples flat =
      revolved(kAxisPoint, kDirection, [](double u) { return Eigen::Vector2d(6 * u, 1); },
               [](double) { return Eigen::Vector2d(0, 1); }, 500, 0, 4);
  const std::optional<Primitive> plane =
      fit_profile_about_direction(flat.points, flat.weights, kDirection, PrimitiveType::Plane);
  ASSERT_TRUE(plane);
  EXPECT_EQ(plane->type, PrimitiveType::Plane);
  EXPECT_LT(max_distance(*plane, flat), 1e-9);
}

TEST(FitProfileAboutDirection, RefusesWhatHasNoDirectionOrBrokenInput)
{
  const SegmentSamples h = hole(kDirection, 0, 5);
  EXPECT_FALSE(fit_profile_about_direction(h.points, h.weights, kDirection, PrimitiveType::Sphere));
  EXPECT_FALSE(fit_profile_about_direction(h.points, h.weights, 2 * kDirection, PrimitiveType::Cylinder));
  EXPECT_FALSE(fit_profile_about_direction(h.points, h.weights.head(10), kDirection, PrimitiveType::Cylinder));
  EXPECT_FALSE(fit_profile_about_direction(h.points.topRows(2), Eigen::VectorXd(), kDirection, PrimitiveType::Cone));
  EXPECT_FALSE(fit_profile_about_direction(Eigen::MatrixX3d(), Eigen::VectorXd(), kDirection, PrimitiveType::Plane));
  Eigen::MatrixX3d bad = h.points;
  bad(7, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(fit_profile_about_direction(bad, h.weights, kDirection, PrimitiveType::Torus));
  EXPECT_FALSE(fit_profile_about_direction(h.points, -h.weights, kDirection, PrimitiveType::Plane));
  // A hole's wall is a line of the meridian parallel to the axis: no cone.
  EXPECT_FALSE(fit_profile_about_direction(h.points, h.weights, kDirection, PrimitiveType::Cone));
}

// Segment 0: the plate's face, whose normal is the part's direction; segment 1: the hole with its own primitive.
struct Plate
{
  std::vector<SegmentSamples> samples;
  std::vector<std::optional<Primitive>> primitives;
  std::vector<PartDirection> directions;
};

Plate plate_with(const SegmentSamples& hole_samples, const Primitive& own)
{
  Plate p;
  p.samples = {revolved(kAxisPoint, kDirection, [](double u) { return Eigen::Vector2d(3 + 20 * u, 5); },
                        [](double) { return Eigen::Vector2d(0, 1); }, 2000, 0, 9),
               hole_samples};
  Primitive face;
  face.origin = kAxisPoint + 5 * kDirection;
  face.axis = kDirection;
  p.primitives = {face, own};
  p.directions = {PartDirection{0, kDirection}};
  return p;
}

// The short hole under noise of 0.3 (the bundled scan's roughness) fitted freely as a torus tilts its axis across the
// hole's; about the plate's normal it is the cylinder of radius 2.75 on the hole's axis.
TEST(FitProfilesAboutDirections, ARoughShortHoleFittedAsATiltedTorusIsItsCylinderAboutThePartsDirection)
{
  const double sigma = 0.3;
  const SegmentSamples h = hole(kDirection, sigma, 11);
  const FitResult torus = fit_primitive(PrimitiveType::Torus, h.points, h.normals, h.weights);
  ASSERT_TRUE(torus.status.ok());
  ASSERT_LT(std::abs(torus.primitive.axis.dot(kDirection)), std::cos(radians_from_degrees(10)))
      << "the free torus follows the direction: nothing to test";
  const Plate p = plate_with(h, torus.primitive);
  const std::vector<SegmentProfile> profiles =
      fit_profiles_about_directions(p.primitives, p.samples, sigma, 0, p.directions, 10);
  ASSERT_EQ(profiles.size(), 1u);
  const SegmentProfile& q = profiles[0];
  EXPECT_EQ(q.segment, 1);
  EXPECT_EQ(q.axis_segment, 0);
  ASSERT_EQ(q.primitive.type, PrimitiveType::Cylinder);
  EXPECT_GT(std::abs(q.primitive.axis.dot(kDirection)), 1 - 1e-12);
  EXPECT_NEAR(q.primitive.radius, 2.75, 0.05);
  EXPECT_LT(off_axis(q.primitive.origin), 0.05);
}

TEST(FitProfilesAboutDirections, AHoleTiltedFromEveryDirectionStaysAsFitted)
{
  const double sigma = 0.1;
  const Eigen::Vector3d tilted = Eigen::AngleAxisd(radians_from_degrees(20), kDirection.unitOrthogonal()) * kDirection;
  const SegmentSamples h = hole(tilted, sigma, 12);
  const FitResult cylinder = fit_primitive(PrimitiveType::Cylinder, h.points, h.normals, h.weights);
  ASSERT_TRUE(cylinder.status.ok());
  const Plate p = plate_with(h, cylinder.primitive);
  EXPECT_TRUE(fit_profiles_about_directions(p.primitives, p.samples, sigma, 0, p.directions, 10).empty());
  // The same hole along the direction, fitted as its cylinder, already follows it.
  const SegmentSamples straight = hole(kDirection, sigma, 13);
  const FitResult along = fit_primitive(PrimitiveType::Cylinder, straight.points, straight.normals, straight.weights);
  ASSERT_TRUE(along.status.ok());
  const Plate q = plate_with(straight, along.primitive);
  EXPECT_TRUE(fit_profiles_about_directions(q.primitives, q.samples, sigma, 0, q.directions, 10).empty());
}

TEST(FitProfilesAboutDirections, TheTypeAskedIsKeptAndBadOptionsChangeNothing)
{
  const double sigma = 0.3;
  const SegmentSamples h = hole(kDirection, sigma, 11);
  const FitResult torus = fit_primitive(PrimitiveType::Torus, h.points, h.normals, h.weights);
  ASSERT_TRUE(torus.status.ok());
  const Plate p = plate_with(h, torus.primitive);
  // Asked to be a cone, the hole becomes the cone about the direction that fits it best, though the cylinder scores
  // better.
  const std::vector<SegmentProfile> cone = fit_profiles_about_directions(
      p.primitives, p.samples, sigma, 0, p.directions, 10, {std::nullopt, PrimitiveType::Cone});
  ASSERT_EQ(cone.size(), 1u);
  EXPECT_EQ(cone[0].primitive.type, PrimitiveType::Cone);
  EXPECT_GT(std::abs(cone[0].primitive.axis.dot(kDirection)), 1 - 1e-12);
  // Asked to be a sphere (no direction) or a plane's own segment: nothing to do.
  EXPECT_TRUE(fit_profiles_about_directions(p.primitives, p.samples, sigma, 0, p.directions, 10,
                                            {std::nullopt, PrimitiveType::Sphere})
                  .empty());
  EXPECT_TRUE(fit_profiles_about_directions(p.primitives, p.samples, sigma, 0, {}, 10).empty());
  EXPECT_TRUE(fit_profiles_about_directions(p.primitives, p.samples, sigma, 0, p.directions, 90).empty());
  EXPECT_TRUE(fit_profiles_about_directions(p.primitives, p.samples, sigma, 0, p.directions, -1).empty());
}

// The part's directions are its planes' normals that hold a share of its area, parallel ones as one class.
TEST(PartDirections, AreTheNormalsOfThePartsLargePlanes)
{
  auto plane = [](const Eigen::Vector3d& normal) {
    Primitive p;
    p.axis = normal.normalized();
    return std::optional<Primitive>(p);
  };
  Primitive hole;
  hole.type = PrimitiveType::Cylinder;
  hole.axis = Eigen::Vector3d::UnitX();
  hole.radius = 2;
  // The top and bottom (z, and z 3 degrees off), a side wall (y), a fillet band fitted flat at 45 degrees holding 3%
  // of the area, a hole (no normal) and a free-form segment.
  const std::vector<std::optional<Primitive>> primitives = {
      plane(Eigen::Vector3d::UnitZ()), plane(Eigen::Vector3d(0, std::sin(0.05), -std::cos(0.05))),
      plane(Eigen::Vector3d::UnitY()), plane(Eigen::Vector3d(0, 1, 1)), hole, std::nullopt};
  const std::vector<double> area = {40, 38, 10, 3, 9, 50};
  const std::vector<PartDirection> d = part_directions(primitives, area, 10);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].segment, 0);
  EXPECT_EQ(d[0].direction, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(d[1].segment, 2);
  // Within 2 degrees the top and bottom are two classes of 40% and 38%; the wall's 10% and the band's 3%.
  EXPECT_EQ(part_directions(primitives, area, 2).size(), 3u);
  EXPECT_TRUE(part_directions(primitives, area, 90).empty());
  EXPECT_TRUE(part_directions(primitives, {}, 10).empty());
}

} // namespace profiles_about_directions_test
