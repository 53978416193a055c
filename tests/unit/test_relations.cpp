// Relations between primitives and their joint refit (common/relate/), on a synthetic machined part: a plate
// with sides, two equal holes, a boss over a coaxial bore, a fillet along an edge, plus a hole tilted on
// purpose. The relations a designer put there are found and hold exactly after the refit; the tilted hole
// gets none; an exact part stays exact.
#include "common/fit/fit_primitive.h"
#include "common/relate/relate_primitives.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <iterator>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace primitive_edit;

// Points on a primitive's patch (plane: a rectangle corner + s u + t v; cylinder: axis from origin, height
// h, angles [a0, a1]), with Gaussian noise along the normal.
struct Patch
{
  Primitive truth;
  SegmentSamples samples;
};

void add_noise(SegmentSamples& s, double sigma, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  for (Eigen::Index i = 0; i < s.points.rows(); ++i)
    s.points.row(i) += sigma * N(rng) * s.normals.row(i);
}

// Fills p.samples with n points of a curved patch of the given area: for each, two uniform draws in [0, 1)
// (the angle's first) go to `place(u, v, point, normal)`; then the noise.
template <class Place>
void sample_patch(Patch& p, int n, double area, double sigma, unsigned seed, Place&& place)
{
  std::mt19937 rng(seed + 1000);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  p.samples.points.resize(n, 3);
  p.samples.normals.resize(n, 3);
  for (int i = 0; i < n; ++i) {
    const double u = U(rng), v = U(rng);
    Eigen::Vector3d point, normal;
    place(u, v, point, normal);
    p.samples.points.row(i) = point.transpose();
    p.samples.normals.row(i) = normal.transpose();
  }
  p.samples.area = area;
  p.samples.weights = Eigen::VectorXd::Constant(n, area / n);
  add_noise(p.samples, sigma, seed);
}

Patch plane_patch(const Eigen::Vector3d& corner, const Eigen::Vector3d& u, const Eigen::Vector3d& v, int n, double sigma,
                  unsigned seed)
{
  Patch p;
  p.truth.type = PrimitiveType::Plane;
  p.truth.origin = corner;
  p.truth.axis = u.cross(v).normalized();
  std::mt19937 rng(seed + 1000);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  p.samples.points.resize(n, 3);
  p.samples.normals.resize(n, 3);
  for (int i = 0; i < n; ++i) {
    p.samples.points.row(i) = (corner + U(rng) * u + U(rng) * v).transpose();
    p.samples.normals.row(i) = p.truth.axis.transpose();
  }
  p.samples.weights = Eigen::VectorXd::Constant(n, u.cross(v).norm() / n);
  p.samples.area = u.cross(v).norm();
  add_noise(p.samples, sigma, seed);
  return p;
}

Patch cylinder_patch(const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double radius, double height, double a0,
                     double a1, int n, double sigma, unsigned seed)
{
  Patch p;
  p.truth.type = PrimitiveType::Cylinder;
  p.truth.origin = base;
  p.truth.axis = axis.normalized();
  p.truth.radius = radius;
  const Eigen::Vector3d e1 = any_orthogonal(p.truth.axis), e2 = p.truth.axis.cross(e1);
  sample_patch(p, n, radius * (a1 - a0) * height, sigma, seed,
               [&](double u, double v, Eigen::Vector3d& point, Eigen::Vector3d& normal) {
                 const double a = a0 + (a1 - a0) * u;
                 normal = std::cos(a) * e1 + std::sin(a) * e2;
                 point = base + height * v * p.truth.axis + radius * normal;
               });
  return p;
}

// A cylinder patch whose angles are measured from a given direction (e1) around the axis.
Patch fillet_patch(const Eigen::Vector3d& base, const Eigen::Vector3d& axis, const Eigen::Vector3d& from,
                   const Eigen::Vector3d& to, double radius, double length, int n, double sigma, unsigned seed)
{
  Patch p;
  p.truth.type = PrimitiveType::Cylinder;
  p.truth.origin = base;
  p.truth.axis = axis.normalized();
  p.truth.radius = radius;
  sample_patch(p, n, radius * kPi / 2 * length, sigma, seed,
               [&](double u, double v, Eigen::Vector3d& point, Eigen::Vector3d& normal) {
                 normal = (std::cos(u * kPi / 2) * from + std::sin(u * kPi / 2) * to).normalized();
                 point = base + length * v * p.truth.axis + radius * normal;
               });
  return p;
}

enum Part { Top, Bottom, SideY, SideX, HoleA, HoleB, Boss, Bore, Fillet, Tilted, PartCount };

struct Scene
{
  std::vector<Patch> patches;
  std::vector<SegmentContact> contacts;
};

Scene make_part(double sigma)
{
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
  Scene s;
  s.patches.resize(PartCount);
  s.patches[Top] = plane_patch(Eigen::Vector3d(0, 1.5, 5), 60 * X, 28.5 * Y, 4000, sigma, 1);
  s.patches[Bottom] = plane_patch(Eigen::Vector3d(0, 0, 0), 30 * Y, 60 * X, 4000, sigma, 2);
  s.patches[SideY] = plane_patch(Eigen::Vector3d(0, 0, 0), 60 * X, 3.5 * Z, 800, sigma, 3);
  s.patches[SideX] = plane_patch(Eigen::Vector3d(0, 0, 0), 5 * Z, 30 * Y, 800, sigma, 4);
  s.patches[HoleA] = cylinder_patch(Eigen::Vector3d(15, 15, 0), Z, 3, 5, 0, 2 * kPi, 1500, sigma, 5);
  s.patches[HoleB] = cylinder_patch(Eigen::Vector3d(45, 15, 0), Z, 3, 5, 0, 2 * kPi, 1500, sigma, 6);
  s.patches[Boss] = cylinder_patch(Eigen::Vector3d(30, 20, 5), Z, 6, 4, 0, 2 * kPi, 1500, sigma, 7);
  s.patches[Bore] = cylinder_patch(Eigen::Vector3d(30, 20, 0), Z, 3.5, 9, 0, 2 * kPi, 1500, sigma, 8);
  // The fillet rounds the edge of the top and the side y = 0: axis along x at y = z - 3.5 = 1.5.
  s.patches[Fillet] = fillet_patch(Eigen::Vector3d(0, 1.5, 3.5), X, -Y, Z, 1.5, 60, 1500, sigma, 9);
  // Tilted on purpose by 8 degrees about y: within the relation angle, but its data says it is tilted.
  const Eigen::Vector3d tilted(std::sin(radians_from_degrees(8)), 0, std::cos(radians_from_degrees(8)));
  s.patches[Tilted] = cylinder_patch(Eigen::Vector3d(52, 8, -3), tilted, 2.2, 11, 0, 2 * kPi, 1500, sigma, 10);
  s.contacts = {{Top, Fillet, 100, Eigen::Vector3d(30, 1.5, 5)}, {SideY, Fillet, 100, Eigen::Vector3d(30, 0, 3.5)}};
  return s;
}

std::vector<std::optional<Primitive>> fit_each(const Scene& s)
{
  std::vector<std::optional<Primitive>> out;
  for (const Patch& p : s.patches) {
    const FitResult r = fit_primitive(p.truth.type, p.samples.points, p.samples.normals, p.samples.weights);
    EXPECT_TRUE(r.status.ok()) << r.status.error;
    out.push_back(r.primitive);
  }
  return out;
}

std::vector<SegmentSamples> samples_of(const Scene& s)
{
  std::vector<SegmentSamples> out;
  for (const Patch& p : s.patches)
    out.push_back(p.samples);
  return out;
}

bool has_relation(const std::vector<Relation>& relations, RelationKind kind, int a, int b)
{
  for (const Relation& r : relations)
    if (r.kind == kind && ((r.a == a && r.b == b) || (r.a == b && r.b == a)))
      return true;
  return false;
}

bool involves(const std::vector<Relation>& relations, int s)
{
  return std::any_of(relations.begin(), relations.end(), [&](const Relation& r) { return r.a == s || r.b == s; });
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return degrees_from_radians(std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))));
}

double axis_offset(const Primitive& a, const Primitive& b)
{
  const Eigen::Vector3d d = b.origin - a.origin;
  return (d - d.dot(a.axis) * a.axis).norm();
}

std::string describe(const std::vector<Relation>& relations)
{
  std::string out;
  for (const Relation& r : relations)
    out += std::string(relation_kind_name(r.kind)) + "(" + std::to_string(r.a) + "," + std::to_string(r.b) + ") ";
  return out;
}

TEST(Relations, FoundAndEnforcedOnANoisyPart)
{
  const Scene scene = make_part(0.05);
  const std::vector<std::optional<Primitive>> fitted = fit_each(scene);
  const RelatedPrimitives r = relate_primitives(fitted, samples_of(scene), scene.contacts, 0.05, RelationOptions());
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  const std::vector<Relation>& rel = r.relations;
  SCOPED_TRACE(describe(rel));
  const std::vector<std::optional<Primitive>>& p = r.primitives;

  // Directions: the top and bottom parallel, the sides square to them and to each other, the holes, boss and
  // bore along z, the fillet along x: all to round-off after the refit.
  for (int s : {Bottom, HoleA, HoleB, Boss, Bore})
    EXPECT_LT(angle_deg(p[Top]->axis, p[std::size_t(s)]->axis), 1e-6) << "segment " << s;
  for (int s : {SideY, SideX, Fillet})
    EXPECT_NEAR(angle_deg(p[Top]->axis, p[std::size_t(s)]->axis), 90, 1e-6) << "segment " << s;
  EXPECT_NEAR(angle_deg(p[SideY]->axis, p[SideX]->axis), 90, 1e-6);
  EXPECT_LT(angle_deg(p[SideX]->axis, p[Fillet]->axis), 1e-6);
  // Positions and sizes: equal holes, the boss over its bore, the fillet tangent to both faces it rounds.
  EXPECT_TRUE(has_relation(rel, RelationKind::EqualRadius, HoleA, HoleB));
  EXPECT_NEAR(p[HoleA]->radius, p[HoleB]->radius, 1e-9);
  EXPECT_TRUE(has_relation(rel, RelationKind::Coaxial, Boss, Bore));
  EXPECT_LT(axis_offset(*p[Boss], *p[Bore]), 1e-9);
  EXPECT_TRUE(has_relation(rel, RelationKind::Tangent, Fillet, Top));
  EXPECT_TRUE(has_relation(rel, RelationKind::Tangent, Fillet, SideY));
  for (int face : {Top, SideY}) {
    const double spine = std::abs(project_onto_primitive(*p[std::size_t(face)], p[Fillet]->origin).signed_distance);
    EXPECT_NEAR(spine, p[Fillet]->radius, 1e-9) << "face " << face;
  }
  // The hole tilted on purpose keeps its own fit.
  EXPECT_FALSE(involves(rel, Tilted));
  EXPECT_NEAR(angle_deg(p[Tilted]->axis, Eigen::Vector3d::UnitZ()), 8, 0.5);
  EXPECT_EQ(p[Tilted]->origin, fitted[Tilted]->origin);

  // Held by the whole part, every direction and the fillet are near the truth.
  for (int s = 0; s < PartCount; ++s) {
    if (s == Tilted)
      continue;
    EXPECT_LT(angle_deg(p[std::size_t(s)]->axis, scene.patches[std::size_t(s)].truth.axis), 0.05) << "segment " << s;
  }
  EXPECT_LT(std::abs(p[Fillet]->radius - 1.5), 0.02);
}

TEST(Relations, AnExactPartStaysExact)
{
  const Scene scene = make_part(0.0);
  const std::vector<std::optional<Primitive>> fitted = fit_each(scene);
  const RelatedPrimitives r = relate_primitives(fitted, samples_of(scene), scene.contacts, 0.0, RelationOptions());
  ASSERT_TRUE(r.status.ok());
  SCOPED_TRACE(describe(r.relations));
  EXPECT_TRUE(has_relation(r.relations, RelationKind::Coaxial, Boss, Bore));
  EXPECT_TRUE(has_relation(r.relations, RelationKind::Tangent, Fillet, Top));
  for (int s = 0; s < PartCount; ++s) {
    const Primitive& truth = scene.patches[std::size_t(s)].truth;
    const Primitive& got = *r.primitives[std::size_t(s)];
    EXPECT_LT(angle_deg(got.axis, truth.axis), 1e-7) << "segment " << s;
    EXPECT_NEAR(got.radius, truth.radius, 1e-8) << "segment " << s;
    // The truth's origin lies on the refitted surface (or axis).
    if (truth.type == PrimitiveType::Plane)
      EXPECT_NEAR(project_onto_primitive(got, truth.origin).signed_distance, 0, 1e-8) << "segment " << s;
    else
      EXPECT_LT(axis_offset(got, truth), 1e-8) << "segment " << s;
  }
}

// Points on a cone band: heights [h0, h1] along the axis from the apex, all the way round.
Patch cone_patch(const Eigen::Vector3d& apex, const Eigen::Vector3d& axis, double half_angle, double h0, double h1,
                 int n, double sigma, unsigned seed)
{
  Patch p;
  p.truth.type = PrimitiveType::Cone;
  p.truth.origin = apex;
  p.truth.axis = axis.normalized();
  p.truth.half_angle = half_angle;
  const Eigen::Vector3d e1 = any_orthogonal(p.truth.axis), e2 = p.truth.axis.cross(e1);
  sample_patch(p, n, kPi * (h0 + h1) * std::tan(half_angle) * (h1 - h0) / std::cos(half_angle), sigma, seed,
               [&](double u, double v, Eigen::Vector3d& point, Eigen::Vector3d& normal) {
                 const double h = h0 + (h1 - h0) * v;
                 const Eigen::Vector3d r = std::cos(2 * kPi * u) * e1 + std::sin(2 * kPi * u) * e2;
                 point = apex + h * p.truth.axis + h * std::tan(half_angle) * r;
                 normal = std::cos(half_angle) * r - std::sin(half_angle) * p.truth.axis;
               });
  return p;
}

// A slender boss (a 5 degree draft, its apex 69 mm below the band) over its bore, both fitted to noisy points:
// the boss's fitted axis is a little off the bore's, which at the apex is millimetres, not at the band.
TEST(Relations, ASlenderConeIsCoaxialWithItsBore)
{
  const double sigma = 0.05, half_angle = radians_from_degrees(5);
  const Eigen::Vector3d Z = Eigen::Vector3d::UnitZ(), centre(30, 20, 0);
  const Patch bore = cylinder_patch(centre, Z, 3.5, 6, 0, 2 * kPi, 1500, sigma, 21);
  const Patch boss = cone_patch(centre - 6.0 / std::tan(half_angle) * Z, Z, half_angle, 6.0 / std::tan(half_angle),
                                6.0 / std::tan(half_angle) + 6, 1500, sigma, 22);
  std::vector<Primitive> fitted;
  std::vector<FitInformation> info;
  for (const Patch* p : {&bore, &boss}) {
    const FitResult r = fit_primitive(p->truth.type, p->samples.points, p->samples.normals, p->samples.weights);
    ASSERT_TRUE(r.status.ok()) << r.status.error;
    fitted.push_back(r.primitive);
    info.push_back(fit_information(r.primitive, p->samples.points, p->samples.weights));
  }
  const double tilt = angle_deg(fitted[0].axis, fitted[1].axis);
  const Eigen::Vector3d apex_offset = fitted[1].origin - fitted[0].origin;
  ASSERT_GT((apex_offset - apex_offset.dot(fitted[0].axis) * fitted[0].axis).norm(), 3 * sigma)
      << "the boss's apex lies on the bore's axis: nothing to show (tilt " << tilt << " degrees)";
  const std::vector<Relation> found = detect_position_relations({&fitted[0], &fitted[1]}, info, {},
                                                                radians_from_degrees(10), 3 * sigma, 1.0, 60);
  SCOPED_TRACE(describe(found));
  EXPECT_TRUE(has_relation(found, RelationKind::Coaxial, 0, 1)) << "tilt " << tilt << " degrees";

  // The refit makes it hold in a few steps: the offset is measured from the axis the boss has at each step,
  // so turning the boss does not read as moving its apex, 69 mm along the axis, off the bore's.
  std::vector<RelatedSegment> segments(2);
  for (int s = 0; s < 2; ++s) {
    const Patch& p = s == 0 ? bore : boss;
    segments[std::size_t(s)].primitive = fitted[std::size_t(s)];
    segments[std::size_t(s)].points = p.samples.points;
    segments[std::size_t(s)].weights = p.samples.weights;
  }
  std::vector<Relation> coaxial;
  std::copy_if(found.begin(), found.end(), std::back_inserter(coaxial),
               [](const Relation& r) { return r.kind == RelationKind::Coaxial; });
  const RelationRefit refit = refit_with_relations(segments, coaxial);
  ASSERT_TRUE(refit.status.ok()) << refit.status.error;
  EXPECT_LE(refit.iterations, 10);
  EXPECT_LT(angle_deg(refit.primitives[0].axis, refit.primitives[1].axis), 1e-6);
  EXPECT_LT(axis_offset(refit.primitives[0], refit.primitives[1]), 1e-6);
}

// Two 45-degree chamfers along the edges of a top face, and one wall, but no face across them (normal x):
// each chamfer is at 45 degrees to both the top and the wall. Held by both angles it is held by two
// constraints tangent to each other at the frame, and the joint refit's step diverged (the 1M-face bracket
// scan lost every relation so); the frame's relations are an independent set instead.
TEST(Relations, ChamfersAtFortyFiveDegreesWithoutAFaceAcrossThem)
{
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
  const double sigma = 0.05;
  enum { Top, Wall, FrontChamfer, BackChamfer, Count };
  Scene scene;
  std::vector<Patch>& patches = scene.patches;
  patches.resize(Count);
  patches[Top] = plane_patch(Eigen::Vector3d(0, 2, 10), 60 * X, 26 * Y, 4000, sigma, 41);
  patches[Wall] = plane_patch(Eigen::Vector3d(0, 0, 0), 60 * X, 8 * Z, 2000, sigma, 42);
  // Narrow, and turned about their edges by 4 and -3 degrees, as a rough scan's narrow faces come out.
  auto turned = [&](double degrees, const Eigen::Vector3d& v) {
    return Eigen::Vector3d(Eigen::AngleAxisd(radians_from_degrees(degrees), X) * v);
  };
  patches[FrontChamfer] = plane_patch(Eigen::Vector3d(0, 0, 8), 60 * X, turned(4, 0.7 * (Y + Z)), 800, sigma, 43);
  patches[BackChamfer] = plane_patch(Eigen::Vector3d(0, 28, 10), 60 * X, turned(-3, 0.7 * (Y - Z)), 800, sigma, 44);
  const std::vector<std::optional<Primitive>> fitted = fit_each(scene);
  const RelatedPrimitives r = relate_primitives(fitted, samples_of(scene), scene.contacts, sigma, RelationOptions());
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  SCOPED_TRACE(describe(r.relations));
  EXPECT_EQ(r.dropped, 0);
  ASSERT_EQ(r.relations.size(), 3u);  // not 2 m - 3 = 5: no pair holds the chamfers' tilt along x
  const std::vector<std::optional<Primitive>>& p = r.primitives;
  EXPECT_NEAR(angle_deg(p[Top]->axis, p[Wall]->axis), 90, 1e-6);
  EXPECT_NEAR(angle_deg(p[Top]->axis, p[FrontChamfer]->axis), 45, 1e-6);
  EXPECT_NEAR(angle_deg(p[FrontChamfer]->axis, p[BackChamfer]->axis), 90, 1e-6);
  // The chamfers turn onto the frame; the large faces, which hold it, stay.
  for (int s : {Top, Wall})
    EXPECT_LT(angle_deg(p[std::size_t(s)]->axis, patches[std::size_t(s)].truth.axis), 0.1) << "segment " << s;
}

// Found by fuzz/fuzz_relate.cpp: with every segment of a relation held fixed (snapped in the edit tool) the
// refit had nothing to move and reported success with the relation broken.
TEST(Relations, ARelationBetweenFixedSegmentsIsCheckedNotAssumed)
{
  const Patch bore =
      cylinder_patch(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d::UnitZ(), 3, 6, 0, 2 * kPi, 500, 0.01, 31);
  const Eigen::Vector3d tilted = Eigen::Vector3d(0.2, 0, 1).normalized();
  const Patch pin = cylinder_patch(Eigen::Vector3d(10, 0, 0), tilted, 1, 6, 0, 2 * kPi, 500, 0.01, 32);
  std::vector<RelatedSegment> segments(2);
  for (int s = 0; s < 2; ++s) {
    const Patch& p = s == 0 ? bore : pin;
    segments[std::size_t(s)].primitive = p.truth;
    segments[std::size_t(s)].points = p.samples.points;
    segments[std::size_t(s)].fixed = true;
  }
  Relation parallel;
  parallel.kind = RelationKind::Parallel;
  parallel.a = 0;
  parallel.b = 1;
  RelationRefit refit = refit_with_relations(segments, {parallel});
  EXPECT_FALSE(refit.status.ok());
  EXPECT_GT(refit.max_violation, 0.1);
  // With one of them free the refit turns it.
  segments[1].fixed = false;
  refit = refit_with_relations(segments, {parallel});
  ASSERT_TRUE(refit.status.ok()) << refit.status.error;
  EXPECT_LT(angle_deg(refit.primitives[0].axis, refit.primitives[1].axis), 1e-6);
  EXPECT_EQ(refit.primitives[0].axis, segments[0].primitive.axis);
}

// The refit spreads its segments' normal equations over threads from kParallelRelationPoints points on; each
// segment's sums are one thread's, so the refit is the same to the last bit on any thread count.
TEST(Relations, RefitIsTheSameOnAnyThreadCount)
{
  std::vector<RelatedSegment> segments(3);
  for (int s = 0; s < 3; ++s) {
    const Eigen::Vector3d axis = Eigen::Vector3d(0.03 * s, 0.02, 1).normalized();
    const Patch p = cylinder_patch(Eigen::Vector3d(8.0 * s, 0, 0), axis, 2 + s, 6, 0, 2 * kPi,
                                   int(kParallelRelationPoints / 2), 0.05, 40 + s);
    segments[std::size_t(s)].primitive =
        fit_primitive(PrimitiveType::Cylinder, p.samples.points, p.samples.normals, p.samples.weights).primitive;
    segments[std::size_t(s)].points = p.samples.points;
  }
  std::vector<Relation> parallel(2);
  for (int r = 0; r < 2; ++r) {
    parallel[std::size_t(r)].kind = RelationKind::Parallel;
    parallel[std::size_t(r)].a = r;
    parallel[std::size_t(r)].b = r + 1;
  }
  const RelationRefit one = refit_with_relations(segments, parallel, kRelationRefitIterations, 1);
  const RelationRefit two = refit_with_relations(segments, parallel, kRelationRefitIterations, 2);
  ASSERT_TRUE(one.status.ok()) << one.status.error;
  ASSERT_TRUE(two.status.ok()) << two.status.error;
  EXPECT_LT(angle_deg(one.primitives[0].axis, one.primitives[2].axis), 1e-6);
  EXPECT_EQ(one.iterations, two.iterations);
  for (int s = 0; s < 3; ++s) {
    EXPECT_EQ(one.primitives[std::size_t(s)].origin, two.primitives[std::size_t(s)].origin) << s;
    EXPECT_EQ(one.primitives[std::size_t(s)].axis, two.primitives[std::size_t(s)].axis) << s;
    EXPECT_EQ(one.primitives[std::size_t(s)].radius, two.primitives[std::size_t(s)].radius) << s;
    EXPECT_EQ(one.rms[std::size_t(s)], two.rms[std::size_t(s)]) << s;
  }
}

TEST(Relations, RefusesBadOptionsAndToleratesFreeFormAndNothing)
{
  const Scene scene = make_part(0.05);
  std::vector<std::optional<Primitive>> fitted = fit_each(scene);
  RelationOptions bad;
  bad.angle_deg = 95;
  EXPECT_FALSE(relate_primitives(fitted, samples_of(scene), scene.contacts, 0.05, bad).status.ok());
  bad = RelationOptions();
  bad.max_cost_increase = std::nan("");
  EXPECT_FALSE(relate_primitives(fitted, samples_of(scene), scene.contacts, 0.05, bad).status.ok());
  // Free-form segments (no primitive) take no part; nothing to relate is no error.
  fitted[Boss].reset();
  const RelatedPrimitives r = relate_primitives(fitted, samples_of(scene), scene.contacts, 0.05, RelationOptions());
  ASSERT_TRUE(r.status.ok());
  EXPECT_FALSE(involves(r.relations, Boss));
  EXPECT_FALSE(r.primitives[Boss].has_value());
  const RelatedPrimitives none = relate_primitives({}, {}, {}, 0.0, RelationOptions());
  EXPECT_TRUE(none.status.ok());
  EXPECT_TRUE(none.relations.empty());
}

// Found by fuzz/fuzz_relate.cpp: a sample at -inf made the part's size unknown (taken as 1) and a coplanar
// relation was kept 0.047 off after the refit. Such samples are refused, as every fit refuses them; a
// free-form segment's samples are not read.
TEST(Relations, RefusesNonFiniteSamples)
{
  const Scene scene = make_part(0.05);
  std::vector<std::optional<Primitive>> fitted = fit_each(scene);
  for (double bad : {-std::numeric_limits<double>::infinity(), std::nan("")}) {
    std::vector<SegmentSamples> samples = samples_of(scene);
    samples[Top].points(3, 0) = bad;
    const RelatedPrimitives r = relate_primitives(fitted, samples, scene.contacts, 0.05, RelationOptions());
    EXPECT_FALSE(r.status.ok());
    EXPECT_NE(r.status.error.find("non-finite"), std::string::npos) << r.status.error;
    EXPECT_TRUE(r.relations.empty());
    for (std::size_t s = 0; s < fitted.size(); ++s)
      EXPECT_TRUE(r.primitives[s].has_value() == fitted[s].has_value() &&
                  (!fitted[s] || r.primitives[s]->origin == fitted[s]->origin));
    samples[Top].points(3, 0) = 0;
    samples[Boss].weights[0] = bad;
    EXPECT_FALSE(relate_primitives(fitted, samples, scene.contacts, 0.05, RelationOptions()).status.ok());
  }
  std::vector<SegmentSamples> samples = samples_of(scene);
  samples[Boss].points(0, 0) = std::nan("");
  fitted[Boss].reset();
  EXPECT_TRUE(relate_primitives(fitted, samples, scene.contacts, 0.05, RelationOptions()).status.ok());
}

// Found by fuzz/fuzz_relate.cpp: a contact naming no segment or one segment twice indexed out of bounds or
// related a fillet to itself; a non-finite noise made every distance tolerance infinite.
TEST(Relations, IgnoresBrokenContactsAndUnknownNoise)
{
  const Scene scene = make_part(0.05);
  const std::vector<std::optional<Primitive>> fitted = fit_each(scene);
  std::vector<SegmentContact> contacts = scene.contacts;
  contacts.push_back({-1, Fillet, 10, Eigen::Vector3d(30, 1.5, 5)});
  contacts.push_back({Fillet, Fillet, 10, Eigen::Vector3d(30, 1.5, 5)});
  const RelatedPrimitives r = relate_primitives(fitted, samples_of(scene), contacts, 0.05, RelationOptions());
  ASSERT_TRUE(r.status.ok());
  for (const Relation& q : r.relations)
    EXPECT_TRUE(q.a != q.b && q.a >= 0 && q.b >= 0) << describe(r.relations);
  EXPECT_TRUE(has_relation(r.relations, RelationKind::Tangent, Fillet, Top)) << describe(r.relations);

  for (double noise : {std::numeric_limits<double>::infinity(), std::nan("")}) {
    const RelatedPrimitives unknown = relate_primitives(fitted, samples_of(scene), scene.contacts, noise, RelationOptions());
    ASSERT_TRUE(unknown.status.ok());
    EXPECT_TRUE(std::isfinite(unknown.distance) && unknown.distance > 0) << unknown.distance;
  }
}

} // namespace
