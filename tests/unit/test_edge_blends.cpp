// Fillets and chamfers between two planes (common/geometry/edge_blend.h, common/relate/fit_edge_blends.h), on the
// edges of a synthetic plate seen in its cross-section: the top z = 5 and the side y = 0 meet along the x axis
// at z = 5, the side and the bottom z = 0 at z = 0. A blend's segment lies between its planes, its borders on the
// tangent lines; a blend found keeps its form, radius and tangency, and what is not a blend stays as fitted.
#include "common/fit/fit_primitive.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/geometry/edge_blend.h"
#include "common/relate/fit_edge_blends.h"

#include "test_fit_data.h"
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

constexpr double kLength = 40; // of the edges, along x

// n points of a profile swept along x: profile(u) gives the point (y, z) and the unit normal (y, z) at u in [0, 1),
// with Gaussian noise of sigma along the normal; the weights share `width * kLength`.
SegmentSamples swept(const std::function<void(double, Eigen::Vector2d&, Eigen::Vector2d&)>& profile, double width,
                     int n, double sigma, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::normal_distribution<double> N(0.0, 1.0);
  SegmentSamples s;
  s.points.resize(n, 3);
  s.normals.resize(n, 3);
  for (int i = 0; i < n; ++i) {
    Eigen::Vector2d p, normal;
    profile(U(rng), p, normal);
    const double x = kLength * U(rng), e = sigma * N(rng);
    s.points.row(i) << x, p.x() + e * normal.x(), p.y() + e * normal.y();
    s.normals.row(i) << 0, normal.x(), normal.y();
  }
  s.area = width * kLength;
  s.weights = Eigen::VectorXd::Constant(n, s.area / n);
  return s;
}

// A straight strip of the profile from a to b, its normal turned to `side`.
SegmentSamples strip(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& side, int n,
                     double sigma, unsigned seed)
{
  Eigen::Vector2d normal(-(b - a).y(), (b - a).x());
  normal.normalize();
  if (normal.dot(side) < 0)
    normal = -normal;
  return swept([&](double u, Eigen::Vector2d& p, Eigen::Vector2d& nrm) { p = a + u * (b - a); nrm = normal; },
               (b - a).norm(), n, sigma, seed);
}

// The quarter circle of radius r rounding the corner at (0, z0) of the side y = 0 (below) and the top z = z0.
SegmentSamples quarter_circle(double z0, double r, int n, double sigma, unsigned seed)
{
  const Eigen::Vector2d centre(r, z0 - r);
  return swept(
      [&](double u, Eigen::Vector2d& p, Eigen::Vector2d& normal) {
        const double a = u * kPi / 2; // from the side (normal -y) to the top (normal +z)
        normal = Eigen::Vector2d(-std::cos(a), std::sin(a));
        p = centre + r * normal;
      },
      r * kPi / 2, n, sigma, seed);
}

SegmentContact contact(int a, int b, double y, double z)
{
  SegmentContact c;
  c.a = std::min(a, b);
  c.b = std::max(a, b);
  c.pairs = 100;
  c.point = c.mean = Eigen::Vector3d(kLength / 2, y, z);
  return c;
}

const SegmentEdgeBlend* blend_of(const std::vector<SegmentEdgeBlend>& blends, int segment)
{
  for (const SegmentEdgeBlend& b : blends)
    if (b.segment == segment)
      return &b;
  return nullptr;
}

// The top, the side and the blend of the top edge (setback s: the blend meets the top at y = s and the side at
// z = 5 - s), with noise sigma; primitives: the true planes, the blend's own automatic fit.
struct TopEdge
{
  enum { Top, Side, Blend };
  std::vector<SegmentSamples> samples;
  std::vector<std::optional<Primitive>> primitives;
  std::vector<SegmentContact> contacts;
};

TopEdge top_edge(BlendForm form, double s, double sigma)
{
  TopEdge e;
  e.samples.push_back(strip({s, 5}, {s + 20, 5}, {0, 1}, 3000, sigma, 1));
  e.samples.push_back(strip({0, 0}, {0, 5 - s}, {-1, 0}, 1500, sigma, 2));
  e.samples.push_back(form == BlendForm::Fillet ? quarter_circle(5, s, 2000, sigma, 3)
                                                : strip({s, 5}, {0, 5 - s}, {-1, 1}, 2000, sigma, 3));
  e.primitives = {test_fit::make_plane({0, 0, 5}, {0, 0, 1}), test_fit::make_plane({0, 0, 0}, {0, -1, 0}),
                  test_segments::auto_fit_or_none(e.samples[2], sigma)};
  e.contacts = {contact(TopEdge::Top, TopEdge::Blend, s, 5), contact(TopEdge::Side, TopEdge::Blend, 0, 5 - s)};
  return e;
}

TEST(EdgeBlend, SectionAndBlendsOfAnExactEdge)
{
  const Primitive top = test_fit::make_plane({0, 0, 5}, {0, 0, 1}), side = test_fit::make_plane({0, 0, 0}, {0, -1, 0});
  const std::optional<EdgeSection> e =
      edge_section(top, side, Eigen::Vector3d(3, 4, 5), Eigen::Vector3d(3, 0, 1), Eigen::Vector3d(7, 1, 1));
  ASSERT_TRUE(e);
  EXPECT_LT((e->origin - Eigen::Vector3d(7, 0, 5)).norm(), 1e-12);
  EXPECT_LT((e->ray_a - Eigen::Vector3d(0, 1, 0)).norm(), 1e-12);
  EXPECT_LT((e->ray_b - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
  EXPECT_NEAR(e->half_angle, kPi / 4, 1e-12);
  const Primitive fillet = edge_blend_primitive(*e, BlendForm::Fillet, 1.5);
  EXPECT_EQ(fillet.type, PrimitiveType::Cylinder);
  EXPECT_NEAR(fillet.radius, 1.5, 1e-12);
  EXPECT_LT((fillet.origin - Eigen::Vector3d(7, 1.5, 3.5)).norm(), 1e-12);
  const double h = 1.5 * std::sqrt(0.5);
  EXPECT_NEAR(edge_blend_distance(*e, BlendForm::Fillet, 1.5, Eigen::Vector3d(2, 1.5 - h, 3.5 + h)), 0, 1e-12);
  const Primitive chamfer = edge_blend_primitive(*e, BlendForm::Chamfer, 1.5);
  EXPECT_EQ(chamfer.type, PrimitiveType::Plane);
  EXPECT_NEAR(edge_blend_distance(*e, BlendForm::Chamfer, 1.5, Eigen::Vector3d(-4, 1.5, 5)), 0, 1e-12);
  EXPECT_NEAR(edge_blend_distance(*e, BlendForm::Chamfer, 1.5, Eigen::Vector3d(9, 0, 3.5)), 0, 1e-12);
  EXPECT_TRUE(in_edge_blend_sector(*e, 1.5, Eigen::Vector3d(0, 0.5, 4.5)));
  EXPECT_FALSE(in_edge_blend_sector(*e, 1.5, Eigen::Vector3d(0, 2, 5)));
  EXPECT_FALSE(in_edge_blend_sector(*e, 1.5, Eigen::Vector3d(0, 0, 3)));
  // Parallel planes meet in no edge; a kept point on the line says no side.
  EXPECT_FALSE(edge_section(top, test_fit::make_plane({0, 0, 0}, {0, 0.2, 1}), {3, 4, 5}, {3, 0, 1}, {0, 0, 0}));
  EXPECT_FALSE(edge_section(top, side, Eigen::Vector3d(3, 0, 5), Eigen::Vector3d(3, 0, 1), Eigen::Vector3d::Zero()));
  EXPECT_FALSE(edge_section(top, side, Eigen::Vector3d::Constant(std::nan("")), Eigen::Vector3d(3, 0, 1),
                            Eigen::Vector3d::Zero()));
}

TEST(EdgeBlends, AnExactFilletStaysExact)
{
  const TopEdge e = top_edge(BlendForm::Fillet, 1.5, 0.0);
  const std::vector<SegmentEdgeBlend> blends = fit_edge_blends(e.primitives, e.samples, e.contacts, 0.0, 0.0);
  ASSERT_EQ(blends.size(), 1u);
  const SegmentEdgeBlend& b = blends[0];
  EXPECT_EQ(b.segment, TopEdge::Blend);
  EXPECT_EQ(b.form, BlendForm::Fillet);
  EXPECT_NEAR(b.primitive.radius, 1.5, 1e-9);
  const Eigen::Vector3d d = b.primitive.origin - Eigen::Vector3d(0, 1.5, 3.5);
  EXPECT_LT((d - d.dot(Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitX()).norm(), 1e-9);
  EXPECT_LT(b.rms, 1e-9);
}

// The scan's case: a 1.5 mm fillet under roughness of 0.3 mm, whose own fit is no cylinder of radius 1.5.
TEST(EdgeBlends, ARoughFilletIsTheCylinderTangentToBothPlanes)
{
  const TopEdge e = top_edge(BlendForm::Fillet, 1.5, 0.3);
  const std::optional<Primitive>& own = e.primitives[TopEdge::Blend];
  EXPECT_FALSE(own && own->type == PrimitiveType::Cylinder && std::abs(own->radius - 1.5) < 0.15);
  const std::vector<SegmentEdgeBlend> blends = fit_edge_blends(e.primitives, e.samples, e.contacts, 0.3, 0.0);
  const SegmentEdgeBlend* b = blend_of(blends, TopEdge::Blend);
  ASSERT_TRUE(b);
  EXPECT_EQ(b->form, BlendForm::Fillet);
  EXPECT_EQ(b->primitive.type, PrimitiveType::Cylinder);
  EXPECT_NEAR(b->primitive.radius, 1.5, 1e-9); // the borders lie on the tangent lines
  // Tangent to both planes: its axis a radius away from each.
  for (const std::optional<Primitive>& p : {e.primitives[TopEdge::Top], e.primitives[TopEdge::Side]})
    EXPECT_NEAR(std::abs((b->primitive.origin - p->origin).dot(p->axis)), b->primitive.radius, 1e-9);
  EXPECT_NEAR(std::abs(b->primitive.axis.x()), 1.0, 1e-12);
  EXPECT_EQ(blends.size(), 1u);
}

TEST(EdgeBlends, ARoughChamferIsThePlaneAtTheBisector)
{
  const TopEdge e = top_edge(BlendForm::Chamfer, 0.8, 0.1);
  const std::vector<SegmentEdgeBlend> blends = fit_edge_blends(e.primitives, e.samples, e.contacts, 0.1, 0.0);
  const SegmentEdgeBlend* b = blend_of(blends, TopEdge::Blend);
  ASSERT_TRUE(b);
  EXPECT_EQ(b->form, BlendForm::Chamfer);
  EXPECT_NEAR(std::abs(b->primitive.axis.dot(Eigen::Vector3d(0, -1, 1).normalized())), 1.0, 1e-12);
  EXPECT_NEAR(std::abs((Eigen::Vector3d(0, 0, 4.2) - b->primitive.origin).dot(b->primitive.axis)), 0, 1e-9);
}

// A 0.8 mm chamfer whose strip the roughness tilts across, as waves wider than the strip do on a CT scan (its ends
// 0.3 mm off the chamfer on either side, noise 0.1): its own plane fits it far closer than the chamfer, so no RMS
// test takes the chamfer, yet with its planes' samples about the edge the chamfer is far likelier than the sharp
// edge, as the segmentation's carve would have found it. A strip of the top beside a sharp edge is no blend.
TEST(EdgeBlends, ATiltedRoughChamferIsFoundByItsLikelihood)
{
  const double tilt = 0.3, sigma = 0.1;
  TopEdge e = top_edge(BlendForm::Chamfer, 0.8, sigma);
  const Eigen::Vector2d across = Eigen::Vector2d(-1, 1).normalized();
  e.samples[TopEdge::Blend] =
      strip(Eigen::Vector2d(0.8, 5) - tilt * across, Eigen::Vector2d(0, 4.2) + tilt * across, {-1, 1}, 2000, sigma, 3);
  e.primitives[TopEdge::Blend] = test_segments::auto_fit_or_none(e.samples[TopEdge::Blend], sigma);
  const std::vector<SegmentEdgeBlend> blends = fit_edge_blends(e.primitives, e.samples, e.contacts, sigma, 0.0);
  const SegmentEdgeBlend* b = blend_of(blends, TopEdge::Blend);
  ASSERT_TRUE(b);
  EXPECT_NEAR(b->setback, 0.8, 1e-9);

  // The faces within 0.8 of a sharp edge on both sides as the segment: its borders and sector are a chamfer's,
  // its own plane fits it closer than the chamfer, and its points say sharp edge.
  TopEdge sharp = top_edge(BlendForm::Chamfer, 0.8, sigma);
  sharp.samples[TopEdge::Top] = strip({0.8, 5}, {20.8, 5}, {0, 1}, 3000, sigma, 1);
  sharp.samples[TopEdge::Side] = strip({0, 0}, {0, 4.2}, {-1, 0}, 1500, sigma, 2);
  const SegmentSamples top = strip({0, 5}, {0.8, 5}, {0, 1}, 1000, sigma, 3);
  const SegmentSamples side = strip({0, 4.2}, {0, 5}, {-1, 0}, 1000, sigma, 4);
  SegmentSamples& corner = sharp.samples[TopEdge::Blend];
  corner.points.resize(2000, 3);
  corner.points << top.points, side.points;
  corner.normals.resize(2000, 3);
  corner.normals << top.normals, side.normals;
  corner.weights.resize(2000);
  corner.weights << top.weights, side.weights;
  corner.area = top.area + side.area;
  sharp.primitives[TopEdge::Blend] = test_segments::auto_fit_or_none(corner, sigma);
  EXPECT_TRUE(fit_edge_blends(sharp.primitives, sharp.samples, sharp.contacts, sigma, 0.0).empty());
}

// Asked to be another type, a segment is a blend of that type or none.
TEST(EdgeBlends, KeepsTheTypesAsked)
{
  const TopEdge e = top_edge(BlendForm::Fillet, 1.5, 0.05);
  std::vector<std::optional<PrimitiveType>> types(3);
  types[TopEdge::Blend] = PrimitiveType::Cone;
  EXPECT_TRUE(fit_edge_blends(e.primitives, e.samples, e.contacts, 0.05, 0.0, types).empty());
  types[TopEdge::Blend] = PrimitiveType::Cylinder;
  const std::vector<SegmentEdgeBlend> cylinder = fit_edge_blends(e.primitives, e.samples, e.contacts, 0.05, 0.0, types);
  ASSERT_EQ(cylinder.size(), 1u);
  EXPECT_EQ(cylinder[0].form, BlendForm::Fillet);
  types[TopEdge::Blend] = PrimitiveType::Plane;
  for (const SegmentEdgeBlend& b : fit_edge_blends(e.primitives, e.samples, e.contacts, 0.05, 0.0, types))
    EXPECT_EQ(b.form, BlendForm::Chamfer);
}

// A narrow face between two planes that no symmetric blend explains: its borders stand 2 and 0.7 from the edge.
TEST(EdgeBlends, AnAsymmetricBevelStaysAsFitted)
{
  TopEdge e = top_edge(BlendForm::Chamfer, 0.8, 0.02);
  e.samples[TopEdge::Blend] = strip({2.0, 5}, {0, 4.3}, {-1, 1}, 2000, 0.02, 3);
  e.primitives[TopEdge::Blend] = test_segments::auto_fit_or_none(e.samples[TopEdge::Blend], 0.02);
  e.contacts = {contact(TopEdge::Top, TopEdge::Blend, 2.0, 5), contact(TopEdge::Side, TopEdge::Blend, 0, 4.3)};
  EXPECT_TRUE(fit_edge_blends(e.primitives, e.samples, e.contacts, 0.02, 0.0).empty());
}

// The bracket's long side: the top, a fillet, a 3 mm wall, a chamfer, the bottom. The fillet's own fit is a plane
// at 45 degrees (as on the scan), so the wall lies between two planes too, and scores as a large fillet of them;
// the narrower blends come first and the wall stays a plane.
TEST(EdgeBlends, AWallBetweenTwoBlendsStaysAPlane)
{
  enum { Top, Fillet, Wall, Chamfer, Bottom };
  const double sigma = 0.3;
  std::vector<SegmentSamples> samples = {
      strip({1.5, 5}, {21.5, 5}, {0, 1}, 3000, sigma, 1),  quarter_circle(5, 1.5, 2000, sigma, 2),
      strip({0, 0.8}, {0, 3.5}, {-1, 0}, 1500, sigma, 3),  strip({0, 0.8}, {0.8, 0}, {-1, -1}, 800, sigma, 4),
      strip({0.8, 0}, {20.8, 0}, {0, -1}, 3000, sigma, 5)};
  std::vector<std::optional<Primitive>> primitives = {
      test_fit::make_plane({0, 0, 5}, {0, 0, 1}),
      fit_primitive(PrimitiveType::Plane, samples[Fillet].points, samples[Fillet].normals, samples[Fillet].weights)
          .primitive,
      test_fit::make_plane({0, 0, 0}, {0, -1, 0}), test_segments::auto_fit_or_none(samples[Chamfer], sigma),
      test_fit::make_plane({0, 0, 0}, {0, 0, -1})};
  const std::vector<SegmentContact> contacts = {contact(Top, Fillet, 1.5, 5), contact(Fillet, Wall, 0, 3.5),
                                                contact(Wall, Chamfer, 0, 0.8), contact(Chamfer, Bottom, 0.8, 0)};
  const std::vector<SegmentEdgeBlend> blends = fit_edge_blends(primitives, samples, contacts, sigma, 0.0);
  const SegmentEdgeBlend* fillet = blend_of(blends, Fillet);
  ASSERT_TRUE(fillet);
  EXPECT_EQ(fillet->form, BlendForm::Fillet);
  EXPECT_EQ(std::min(fillet->plane_a, fillet->plane_b), int(Top));
  EXPECT_EQ(std::max(fillet->plane_a, fillet->plane_b), int(Wall));
  EXPECT_FALSE(blend_of(blends, Wall));
  EXPECT_FALSE(blend_of(blends, Top));
  EXPECT_FALSE(blend_of(blends, Bottom));
  for (const SegmentEdgeBlend& b : blends)
    for (const SegmentEdgeBlend& c : blends)
      EXPECT_TRUE(b.plane_a != c.segment && b.plane_b != c.segment);
}

TEST(EdgeBlends, ToleratesBrokenInput)
{
  TopEdge e = top_edge(BlendForm::Fillet, 1.5, 0.05);
  // Contacts out of range or with a point not finite, a segment with no samples: nothing, no crash.
  std::vector<SegmentContact> broken = e.contacts;
  broken.push_back(contact(-1, 7, 0, 0));
  broken.back().a = -1;
  SegmentContact nan = contact(TopEdge::Top, TopEdge::Side, 0, 0);
  nan.mean = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  broken.push_back(nan);
  EXPECT_EQ(fit_edge_blends(e.primitives, e.samples, broken, 0.05, 0.0).size(), 1u);
  EXPECT_TRUE(fit_edge_blends(e.primitives, e.samples, {}, 0.05, 0.0).empty());
  EXPECT_TRUE(fit_edge_blends({}, {}, e.contacts, 0.05, 0.0).empty());
  std::vector<SegmentSamples> bad = e.samples;
  bad[TopEdge::Blend].points(3, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(fit_edge_blends(e.primitives, bad, e.contacts, 0.05, 0.0).empty());
  bad = e.samples;
  bad[TopEdge::Blend].weights[0] = -1;
  EXPECT_TRUE(fit_edge_blends(e.primitives, bad, e.contacts, 0.05, 0.0).empty());
  bad[TopEdge::Blend] = SegmentSamples();
  EXPECT_TRUE(fit_edge_blends(e.primitives, bad, e.contacts, 0.05, 0.0).empty());
  // An infinite tolerance measures nothing.
  const double infinite = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(fit_edge_blends(e.primitives, e.samples, e.contacts, 0.05, infinite).empty());
  // A plane that is no valid plane is no support.
  e.primitives[TopEdge::Top]->axis = Eigen::Vector3d::Zero();
  EXPECT_TRUE(fit_edge_blends(e.primitives, e.samples, e.contacts, 0.05, 0.0).empty());
}

} // namespace
