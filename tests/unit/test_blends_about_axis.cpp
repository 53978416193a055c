// Fillets and chamfers between a plane and a cylinder turning about its normal (common/geometry/meridian_section.h,
// common/relate/fit_edge_blends.h): a boss of radius 8 standing on the plane z = 5 with a foot rounded by a torus
// of tube radius 2, and a hole of radius 4 in the plane z = 0 with a 45-degree countersink of 1 mm. The blend's
// borders are rings whose mean lies on the axis; a blend found is the torus or cone tangent to both neighbours.
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/edge_blend.h"
#include "common/geometry/meridian_section.h"
#include "common/relate/fit_edge_blends.h"

#include "test_fit_data.h"
#include "test_segment_samples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

namespace {

using namespace primitive_edit;

const Eigen::Vector3d kAxisPoint(30, 20, 0);

// The straight profile from a to b in (r, h) about the axis through kAxisPoint along z, its normal turned towards
// `side`.
SegmentSamples turned_line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& side, int n,
                           double sigma, unsigned seed)
{
  Eigen::Vector2d normal(-(b - a).y(), (b - a).x());
  normal.normalize();
  if (normal.dot(side) < 0)
    normal = -normal;
  return test_segments::revolved(
      kAxisPoint, Eigen::Vector3d::UnitZ(), [&](double u) -> Eigen::Vector2d { return a + u * (b - a); },
      [&](double) { return normal; }, n, sigma, seed, kPi * (a.x() + b.x()) * (b - a).norm());
}

// A border ring of radius r at height h: its points, and their mean on the axis.
SegmentContact ring(int a, int b, double r, double h)
{
  SegmentContact c;
  c.a = std::min(a, b);
  c.b = std::max(a, b);
  c.pairs = 200;
  for (int k = 0; k < 64; ++k) {
    const double angle = 2 * kPi * k / 64;
    c.points.push_back(kAxisPoint + Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle), h));
  }
  c.point = c.points.front();
  c.mean = kAxisPoint + Eigen::Vector3d(0, 0, h);
  return c;
}

// Plane z = 5 (r from 10 to 20), the boss r = 8 (z from 7 to 15) and the foot's torus between them.
struct BossFoot
{
  enum { Plane, Boss, Foot };
  std::vector<SegmentSamples> samples;
  std::vector<std::optional<Primitive>> primitives;
  std::vector<SegmentContact> contacts;
};

BossFoot boss_foot(double sigma)
{
  BossFoot e;
  e.samples.push_back(turned_line({10, 5}, {20, 5}, {0, 1}, 3000, sigma, 1));
  e.samples.push_back(turned_line({8, 7}, {8, 15}, {1, 0}, 3000, sigma, 2));
  // From the plane (normal +h) to the boss (normal +r), facing the tube's centre (10, 7).
  auto facing = [](double u) { return Eigen::Vector2d(std::sin(u * kPi / 2), std::cos(u * kPi / 2)); };
  auto arc = [&](double u) -> Eigen::Vector2d { return Eigen::Vector2d(10, 7) - 2 * facing(u); };
  // Its area by Pappus: the arc's length times the path of its centroid.
  e.samples.push_back(test_segments::revolved(kAxisPoint, Eigen::Vector3d::UnitZ(), arc, facing, 3000, sigma, 3,
                                              2 * kPi * (10 - 4 / kPi) * kPi));
  e.primitives = {test_fit::make_plane(kAxisPoint + Eigen::Vector3d(0, 0, 5), {0, 0, 1}),
                  test_fit::make_cylinder(kAxisPoint, {0, 0, 1}, 8),
                  test_segments::auto_fit_or_none(e.samples[2], sigma)};
  e.contacts = {ring(BossFoot::Plane, BossFoot::Foot, 10, 5), ring(BossFoot::Boss, BossFoot::Foot, 8, 7)};
  return e;
}

TEST(MeridianSection, MapsTurnsBackAndMeasuresAsTheSurfaceOfRevolution)
{
  const Primitive boss = test_fit::make_cylinder(kAxisPoint, {0, 0, 1}, 8);
  const std::optional<MeridianFrame> f = meridian_frame(boss.origin, boss.axis, kAxisPoint + Eigen::Vector3d(3, 4, 9));
  ASSERT_TRUE(f);
  const std::optional<Primitive> wall = meridian_of_turned(*f, boss);
  ASSERT_TRUE(wall);
  const Eigen::Vector3d p = kAxisPoint + Eigen::Vector3d(-6, 8, 2.5);
  const Eigen::Vector3d q = to_meridian(*f, p);
  EXPECT_NEAR(q.x(), 10, 1e-12);
  EXPECT_NEAR(q.y(), 2.5, 1e-12);
  EXPECT_LT((from_meridian(*f, q) - p).norm(), 1e-12);
  // The cylinder is r = 8; the plane z = 5 the line h = 5, even seen from far along it.
  EXPECT_NEAR(wall->axis.dot(Eigen::Vector3d(8, 3, 0) - wall->origin), 0, 1e-12);
  const std::optional<Primitive> level =
      meridian_of_plane(*f, test_fit::make_plane({0, 0, 5}, {0, 0, 1}), Eigen::Vector3d(100, -50, 7));
  ASSERT_TRUE(level);
  EXPECT_NEAR(level->axis.dot(Eigen::Vector3d(2, 5, 0) - level->origin), 0, 1e-12);
  // A plane along the axis has no level line; a sphere is no turned surface; a point on the axis has no angle.
  EXPECT_FALSE(meridian_of_plane(*f, test_fit::make_plane({0, 0, 0}, {1, 0, 0}), p));
  EXPECT_FALSE(meridian_of_turned(*f, test_fit::make_sphere({0, 0, 0}, 1)));
  EXPECT_FALSE(meridian_frame(boss.origin, boss.axis, kAxisPoint + Eigen::Vector3d(0, 0, 3)));
  EXPECT_FALSE(meridian_frame(boss.origin, Eigen::Vector3d::Zero(), p));
  // A cone opening downwards with its apex at h = 15: the line through (8, 7) at 45 degrees.
  const std::optional<Primitive> cone_line =
      meridian_of_turned(*f, test_fit::make_cone(kAxisPoint + Eigen::Vector3d(0, 0, 15), {0, 0, -1}, kPi / 4));
  ASSERT_TRUE(cone_line);
  EXPECT_NEAR(cone_line->axis.dot(Eigen::Vector3d(8, 7, 0) - cone_line->origin), 0, 1e-12);
  EXPECT_NEAR(cone_line->axis.dot(Eigen::Vector3d(0, 15, 0) - cone_line->origin), 0, 1e-12);
  // The band's extent in (r, h): from (6, -1) to (10, 2).
  Eigen::MatrixX3d band(3, 3);
  band << 36, 20, -1, 30, 30, 2, 22, 20, 0.5;
  EXPECT_NEAR(meridian_extent(*f, band, Eigen::VectorXd()), 5, 1e-12);

  // The foot's fillet of the corner (8, 5) with setback 2: the torus of major radius 10 and tube 2 at height 7;
  // its distance in the meridian is the 3D distance to that torus.
  const std::optional<EdgeSection> section =
      edge_section(*level, *wall, Eigen::Vector3d(12, 5, 0), Eigen::Vector3d(8, 9, 0), Eigen::Vector3d(8, 5, 0));
  ASSERT_TRUE(section);
  const std::optional<Primitive> torus = revolve(*f, edge_blend_primitive(*section, BlendForm::Fillet, 2));
  ASSERT_TRUE(torus);
  EXPECT_EQ(torus->type, PrimitiveType::Torus);
  EXPECT_NEAR(torus->radius, 10, 1e-12);
  EXPECT_NEAR(torus->minor_radius, 2, 1e-12);
  EXPECT_LT((torus->origin - (kAxisPoint + Eigen::Vector3d(0, 0, 7))).norm(), 1e-12);
  for (const Eigen::Vector3d& x :
       {Eigen::Vector3d(31, 29, 6), Eigen::Vector3d(20, 25, 5.5), Eigen::Vector3d(38, 20, 8)})
    EXPECT_NEAR(edge_blend_distance(*section, BlendForm::Fillet, 2, to_meridian(*f, x)),
                std::abs(project_onto_primitive(*torus, x).signed_distance), 1e-9);
  // Its chamfer: the cone through (10, 5) and (8, 7), apex on the axis at h = 15, opening downwards at 45 degrees.
  const std::optional<Primitive> cone = revolve(*f, edge_blend_primitive(*section, BlendForm::Chamfer, 2));
  ASSERT_TRUE(cone);
  EXPECT_EQ(cone->type, PrimitiveType::Cone);
  EXPECT_NEAR(cone->half_angle, kPi / 4, 1e-12);
  EXPECT_LT((cone->origin - (kAxisPoint + Eigen::Vector3d(0, 0, 15))).norm(), 1e-9);
  EXPECT_LT((cone->axis - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
}

TEST(BlendsAboutAxis, TheBossFootIsTheTorusTangentToPlaneAndBoss)
{
  for (const double sigma : {0.0, 0.05}) {
    SCOPED_TRACE(sigma);
    const BossFoot e = boss_foot(sigma);
    const std::vector<SegmentEdgeBlend> blends =
        fit_edge_blends(e.primitives, e.samples, e.contacts, sigma, 0.0, {}, {}, 10.0);
    ASSERT_EQ(blends.size(), 1u);
    const SegmentEdgeBlend& b = blends[0];
    EXPECT_EQ(b.segment, BossFoot::Foot);
    EXPECT_EQ(b.plane_a, BossFoot::Plane);
    EXPECT_EQ(b.plane_b, BossFoot::Boss);
    EXPECT_EQ(b.form, BlendForm::Fillet);
    ASSERT_TRUE(b.meridian);
    ASSERT_EQ(b.primitive.type, PrimitiveType::Torus);
    EXPECT_NEAR(b.primitive.minor_radius, 2, sigma > 0 ? 0.05 : 1e-9);
    EXPECT_NEAR(b.primitive.radius, 10, sigma > 0 ? 0.05 : 1e-9);
    EXPECT_GT(std::abs(b.primitive.axis.z()), 1 - 1e-12);
    // Tangent to both: the tube's circle is its radius from the plane and from the boss.
    EXPECT_NEAR(b.primitive.origin.z() - 5, b.primitive.minor_radius, 1e-9);
    EXPECT_NEAR(b.primitive.radius - 8, b.primitive.minor_radius, 1e-9);
    // The contacts lie on the tangent circles: on the plane at r = 10, on the boss at h = 7.
    EXPECT_NEAR(b.contact_a.z(), 5, 1e-9);
    EXPECT_NEAR((b.contact_b - kAxisPoint).head<2>().norm(), 8, 1e-9);
  }
}

TEST(BlendsAboutAxis, TheCountersinkIsTheConeOfTheHole)
{
  // The plane z = 0 (r from 5 to 15, material below), the hole r = 4 (z from -10 to -1), the chamfer from (5, 0)
  // to (4, -1).
  const double sigma = 0.03;
  std::vector<SegmentSamples> samples{turned_line({5, 0}, {15, 0}, {0, 1}, 3000, sigma, 4),
                                      turned_line({4, -1}, {4, -10}, {-1, 0}, 3000, sigma, 5),
                                      turned_line({5, 0}, {4, -1}, {-1, 1}, 2000, sigma, 6)};
  std::vector<std::optional<Primitive>> primitives{test_fit::make_plane(kAxisPoint, {0, 0, 1}),
                                                   test_fit::make_cylinder(kAxisPoint, {0, 0, 1}, 4),
                                                   test_segments::auto_fit_or_none(samples[2], sigma)};
  const std::vector<SegmentContact> contacts{ring(0, 2, 5, 0), ring(1, 2, 4, -1)};
  const std::vector<SegmentEdgeBlend> blends = fit_edge_blends(primitives, samples, contacts, sigma, 0.0, {}, {}, 10.0);
  ASSERT_EQ(blends.size(), 1u);
  const SegmentEdgeBlend& b = blends[0];
  EXPECT_EQ(b.segment, 2);
  EXPECT_EQ(b.form, BlendForm::Chamfer);
  ASSERT_EQ(b.primitive.type, PrimitiveType::Cone);
  EXPECT_NEAR(b.primitive.half_angle, kPi / 4, 1e-9);
  // The cone through (5, 0) and (4, -1) has its apex on the axis at z = -5 and opens upwards.
  EXPECT_LT((b.primitive.origin - (kAxisPoint + Eigen::Vector3d(0, 0, -5))).norm(), 1e-9);
  EXPECT_GT(b.primitive.axis.z(), 1 - 1e-12);
}

TEST(BlendsAboutAxis, NoneWithoutTheAngleATypeThatRulesThemOutOrATiltedBoss)
{
  const double sigma = 0.05;
  const BossFoot e = boss_foot(sigma);
  // The angle 0 leaves blends about an axis out, as before them.
  EXPECT_TRUE(fit_edge_blends(e.primitives, e.samples, e.contacts, sigma, 0.0).empty());
  // A foot asked to be a sphere or a cylinder is no torus; asked a torus, it is the fillet.
  std::vector<std::optional<PrimitiveType>> types(3);
  for (PrimitiveType t : {PrimitiveType::Sphere, PrimitiveType::Cylinder, PrimitiveType::Cone}) {
    types[BossFoot::Foot] = t;
    EXPECT_TRUE(fit_edge_blends(e.primitives, e.samples, e.contacts, sigma, 0.0, types, {}, 10.0).empty());
  }
  types[BossFoot::Foot] = PrimitiveType::Torus;
  ASSERT_EQ(fit_edge_blends(e.primitives, e.samples, e.contacts, sigma, 0.0, types, {}, 10.0).size(), 1u);
  // A boss tilted 20 degrees from the plane's normal turns about no axis the plane shares.
  BossFoot tilted = e;
  tilted.primitives[BossFoot::Boss]->axis = Eigen::Vector3d(std::sin(0.35), 0, std::cos(0.35));
  EXPECT_TRUE(fit_edge_blends(tilted.primitives, tilted.samples, tilted.contacts, sigma, 0.0, {}, {}, 10.0).empty());
}

} // namespace
