// Tests of snap_segments on the tests' mesh type and on MeshLab's CMeshO: parameter overrides, sharp
// edges and corners, flip prevention, unsnapped segments and bad input.
#include "common/base/constants.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/snap/describe_snap_report.h"
#include "common/snap/snap_segments.h"
#include "plate_with_hole.h"
#include "rounded_box.h"
#include "test_fit_data.h"
#include "test_mesh.h"

#include "meshlab_test_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <type_traits>
#include <vector>

using namespace primitive_edit;

namespace {

using plate_fixture::build_mesh;
using plate_fixture::make_rounded_box;
using plate_fixture::RoundedBox;
using plate_fixture::Soup;
using test_fit::make_cylinder;
using test_fit::make_plane;

template <class C>
Eigen::Vector3d eig(const C& c)
{
  return Eigen::Vector3d(double(c[0]), double(c[1]), double(c[2]));
}

template <class M>
Eigen::Vector3d face_normal(const M& m, size_t f)
{
  const Eigen::Vector3d a = eig(m.face[f].cP(0));
  return (eig(m.face[f].cP(1)) - a).cross(eig(m.face[f].cP(2)) - a);
}

// Geometric tolerance for a mesh of the given size: float coordinates (CMeshO) only hold ~7 digits.
template <class M>
double tolerance(double size)
{
  return std::is_same<typename M::ScalarType, float>::value ? 1e-5 * size : 1e-9 * size;
}

// A tube (open at both ends) around the axis through `origin` along unit `axis`, radius(angle, height)
// giving the distance from the axis; faces point outwards.
template <class RadiusFn>
Soup make_tube(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis, double height, int around, int along,
               RadiusFn radius)
{
  const Eigen::Vector3d u1 = any_orthogonal(axis), u2 = axis.cross(u1);
  Soup s;
  for (int k = 0; k <= along; ++k)
    for (int j = 0; j < around; ++j) {
      const double t = 2 * kPi * j / around, h = height * k / along;
      s.points.push_back(origin + h * axis + radius(t, h) * (std::cos(t) * u1 + std::sin(t) * u2));
    }
  auto id = [&](int k, int j) { return k * around + (j % around); };
  for (int k = 0; k < along; ++k)
    for (int j = 0; j < around; ++j) {
      s.triangles.push_back({id(k, j), id(k, j + 1), id(k + 1, j + 1)});
      s.triangles.push_back({id(k, j), id(k + 1, j + 1), id(k + 1, j)});
    }
  s.labels.assign(s.triangles.size(), 0);
  return s;
}

template <class M>
class SnapSegmentsTest : public ::testing::Test {};

using MeshTypes = ::testing::Types<test_mesh::TMesh, test_mesh::MeshLabMesh>;
TYPED_TEST_SUITE(SnapSegmentsTest, MeshTypes, );

} // namespace

// The example: a tube fitted at radius 4.8, edited to radius 5, must become a radius-5 cylinder.
TYPED_TEST(SnapSegmentsTest, CylinderRadiusOverride)
{
  using M = TypeParam;
  const Eigen::Vector3d origin(1, -2, 0.5), axis = Eigen::Vector3d(1, 2, 2).normalized();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  const Soup tube = make_tube(origin, axis, 10.0, 64, 40, [&](double, double) { return 4.8 + noise(rng); });
  M m;
  build_mesh(m, tube);
  const Primitive edited = make_cylinder(origin, axis, 5.0);
  const SnapReport report = snap_segments(m, tube.labels, {edited});
  EXPECT_EQ(report.moved_vertices, static_cast<int>(m.vert.size()));
  EXPECT_EQ(report.edge_vertices, 0);
  EXPECT_EQ(report.border_vertices, 0);
  EXPECT_EQ(report.reverted_vertices, 0);
  double mean = 0, worst = 0;
  for (const auto& v : m.vert) {
    const double d = std::abs(signed_distance_to_primitive(edited, eig(v.cP())));
    mean += d;
    worst = std::max(worst, d);
  }
  mean /= double(m.vert.size());
  EXPECT_LT(mean, tolerance<M>(10.0));
  EXPECT_LT(worst, tolerance<M>(10.0));
  EXPECT_GT(report.mean_displacement, 0.15);
  EXPECT_LT(report.max_displacement, 0.26);
}

// Blurred box edges come out sharp: corners at the exact corners, edge vertices on the edge lines.
TYPED_TEST(SnapSegmentsTest, BoxEdgesAndCornersBecomeSharp)
{
  using M = TypeParam;
  const Eigen::Matrix3d rot =
      (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX())).toRotationMatrix();
  const Eigen::Vector3d shift(2, -1, 3);
  const RoundedBox box = make_rounded_box({10, 6, 4}, 0.25, 0.3, 0.02, 12345, rot, shift);
  M m;
  build_mesh(m, box.soup);
  const SnapReport report = snap_segments(m, box.soup.labels, box.planes);

  int corners = 0, edges = 0;
  for (size_t v = 0; v < m.vert.size(); ++v) {
    const Eigen::Vector3d x = eig(m.vert[v].cP());
    const Eigen::Vector3d exact = rot * box.lattice[v] + shift;
    if (box.bound[v] == 3) {
      ++corners;
      EXPECT_LT((x - exact).norm(), 1e-4) << "corner " << v;
    } else if (box.bound[v] == 2) {
      ++edges;
      // The edge runs along the one axis whose lattice coordinate is not at a bound.
      Eigen::Vector3d dir = Eigen::Vector3d::Zero();
      for (int a = 0; a < 3; ++a)
        if (box.lattice[v][a] > 1e-9 && box.lattice[v][a] < Eigen::Vector3d(10, 6, 4)[a] - 1e-9)
          dir[a] = 1;
      dir = rot * dir;
      const Eigen::Vector3d off = x - exact;
      EXPECT_LT((off - off.dot(dir) * dir).norm(), tolerance<M>(10.0)) << "edge vertex " << v;
    }
  }
  EXPECT_EQ(corners, 8);
  EXPECT_EQ(report.corner_vertices, 8);
  EXPECT_EQ(report.edge_vertices, edges);
  EXPECT_EQ(report.border_vertices, corners + edges);
  EXPECT_EQ(report.reverted_vertices, 0);
  EXPECT_EQ(report.moved_vertices, static_cast<int>(m.vert.size()));
  for (size_t f = 0; f < m.face.size(); ++f) {
    const Primitive& side = *box.planes[static_cast<size_t>(box.soup.labels[f])];
    EXPECT_GT(face_normal(m, f).normalized().dot(side.axis), 0.99) << "face " << f;
    for (int j = 0; j < 3; ++j)
      EXPECT_LT(std::abs(signed_distance_to_primitive(side, eig(m.face[f].cP(j)))), tolerance<M>(10.0));
  }
}

// A cylinder with a flat cap and a rounded rim: the rim goes onto the plane/cylinder circle; without
// sharp edges each rim vertex goes onto just one of the two surfaces.
TYPED_TEST(SnapSegmentsTest, PlaneCylinderRim)
{
  using M = TypeParam;
  const double radius = 5, height = 6, bevel = 0.2;
  const int around = 48, along = 12, cap_rings = 8;
  Soup s = make_tube({0, 0, 0}, {0, 0, 1}, height, around, along, [&](double, double h) {
    return h >= height ? radius - bevel : radius;
  });
  const int rim = along * around;
  for (int j = 0; j < around; ++j)
    s.points[static_cast<size_t>(rim + j)].z() -= bevel;
  // The cap: concentric rings down to a centre vertex, faces pointing up, label 1.
  std::vector<int> outer(static_cast<size_t>(around));
  for (int j = 0; j < around; ++j)
    outer[static_cast<size_t>(j)] = rim + j;
  for (int i = 1; i <= cap_rings; ++i) {
    std::vector<int> inner;
    if (i == cap_rings) {
      inner.assign(static_cast<size_t>(around), static_cast<int>(s.points.size()));
      s.points.emplace_back(0, 0, height);
    } else {
      const double r = radius * (cap_rings - i) / cap_rings;
      for (int j = 0; j < around; ++j) {
        const double t = 2 * kPi * j / around;
        inner.push_back(static_cast<int>(s.points.size()));
        // Same angular frame as make_tube, so the rings line up with the rim.
        const Eigen::Vector3d u1 = any_orthogonal(Eigen::Vector3d::UnitZ()), u2 = Eigen::Vector3d::UnitZ().cross(u1);
        s.points.push_back(r * (std::cos(t) * u1 + std::sin(t) * u2) +
                           Eigen::Vector3d(0, 0, height + 0.01 * std::sin(5 * t)));
      }
    }
    for (int j = 0; j < around; ++j) {
      const size_t a = static_cast<size_t>(j), b = static_cast<size_t>((j + 1) % around);
      s.triangles.push_back({outer[a], outer[b], inner[b]});
      s.labels.push_back(1);
      if (i < cap_rings) {
        s.triangles.push_back({outer[a], inner[b], inner[a]});
        s.labels.push_back(1);
      }
    }
    outer = inner;
  }
  const Primitive wall = make_cylinder({0, 0, 0}, {0, 0, 1}, radius);
  const Primitive top = make_plane({0, 0, height}, {0, 0, 1});

  M sharp;
  build_mesh(sharp, s);
  const SnapReport report = snap_segments(sharp, s.labels, {wall, top});
  EXPECT_EQ(report.edge_vertices, around);
  EXPECT_EQ(report.border_vertices, around);
  EXPECT_EQ(report.reverted_vertices, 0);
  for (int j = 0; j < around; ++j) {
    const Eigen::Vector3d x = eig(sharp.vert[static_cast<size_t>(rim + j)].cP());
    EXPECT_LT(std::abs(signed_distance_to_primitive(wall, x)), tolerance<M>(radius));
    EXPECT_LT(std::abs(signed_distance_to_primitive(top, x)), tolerance<M>(radius));
  }
  for (size_t f = 0; f < sharp.face.size(); ++f) {
    const Eigen::Vector3d n = face_normal(sharp, f).normalized();
    if (s.labels[f] == 1) {
      EXPECT_GT(n.z(), 0.99);
    } else {
      EXPECT_LT(std::abs(n.z()), 0.1);
    }
  }

  M soft;
  build_mesh(soft, s);
  SnapOptions options;
  options.sharp_edges = false;
  const SnapReport soft_report = snap_segments(soft, s.labels, {wall, top}, options);
  EXPECT_EQ(soft_report.edge_vertices, 0);
  EXPECT_EQ(soft_report.border_vertices, around); // still on the border, but left off its edge
  int on_both = 0;
  for (int j = 0; j < around; ++j) {
    const Eigen::Vector3d x = eig(soft.vert[static_cast<size_t>(rim + j)].cP());
    const bool on_wall = std::abs(signed_distance_to_primitive(wall, x)) < tolerance<M>(radius);
    const bool on_top = std::abs(signed_distance_to_primitive(top, x)) < tolerance<M>(radius);
    EXPECT_TRUE(on_wall || on_top);
    on_both += (on_wall && on_top) ? 1 : 0;
  }
  EXPECT_EQ(on_both, 0);
}

// Whether snapping the soup onto the ball without the guard flips its face 0: the setups below must.
template <class M>
bool flips_without_guard(const Soup& s, const Primitive& ball, SnapOptions options = {})
{
  M m;
  build_mesh(m, s);
  const Eigen::Vector3d before = face_normal(m, 0);
  options.prevent_flips = false;
  snap_segments(m, s.labels, {ball}, options);
  return face_normal(m, 0).dot(before) < 0;
}

Primitive unit_ball()
{
  Primitive ball;
  ball.type = PrimitiveType::Sphere;
  ball.radius = 1;
  return ball;
}

// A triangle whose inner vertex would be projected across the opposite edge: snapping it would flip the face.
// One of the two outer vertices slides along the sphere to the mean of its neighbours, which unfolds it: every
// vertex stays on the sphere, none goes back to the scan.
TYPED_TEST(SnapSegmentsTest, FlippedFaceUnfoldsOnItsSurface)
{
  using M = TypeParam;
  Soup s;
  s.points = {{1, 0, 0}, {0, 1, 0}, {0.3, 0.3, -0.01}};
  s.triangles = {{0, 1, 2}};
  s.labels = {0};
  const Primitive ball = unit_ball();
  ASSERT_TRUE(flips_without_guard<M>(s, ball)) << "the setup must flip without the guard";

  M m;
  build_mesh(m, s);
  const Eigen::Vector3d before = face_normal(m, 0);
  const SnapReport report = snap_segments(m, s.labels, {ball});
  EXPECT_GT(face_normal(m, 0).dot(before), 0);
  EXPECT_EQ(report.reverted_vertices, 1);
  EXPECT_EQ(report.partway_vertices, 0);
  EXPECT_EQ(report.folded_faces, 0);
  for (int v = 0; v < 3; ++v)
    EXPECT_LT(std::abs(signed_distance_to_primitive(ball, eig(m.vert[size_t(v)].cP()))), tolerance<M>(1.0))
        << "vertex " << v;
}

// The same triangle with faces on the far side of its outer vertices, which hold the means of their neighbours
// near them: no vertex's step along the sphere unfolds it, nor the mean of the inner vertex's two neighbours (on
// that edge), so the inner vertex goes back to where it was, then as far towards the sphere as the face allows:
// 7/16 of the way (the edge x + y = 1 is crossed at 0.49).
TYPED_TEST(SnapSegmentsTest, FlippingVertexFallsBack)
{
  using M = TypeParam;
  Soup s;
  const auto on_ball = [](double x, double y, double z) { return Eigen::Vector3d(x, y, z).normalized(); };
  s.points = {{1, 0, 0}, {0, 1, 0}, {0.3, 0.3, -0.01}, on_ball(0.6, -0.8, 0), on_ball(0.8, -0.36, -0.48),
              on_ball(-0.8, 0.6, 0), on_ball(-0.36, 0.8, -0.48)};
  s.triangles = {{0, 1, 2}, {0, 3, 4}, {1, 5, 6}};
  s.labels = {0, 0, 0};
  const Primitive ball = unit_ball();
  ASSERT_TRUE(flips_without_guard<M>(s, ball)) << "the setup must flip without the guard";

  M m;
  build_mesh(m, s);
  const Eigen::Vector3d before = face_normal(m, 0);
  const Eigen::Vector3d inner = eig(m.vert[2].cP());
  const SnapReport report = snap_segments(m, s.labels, {ball});
  EXPECT_GT(face_normal(m, 0).dot(before), 0);
  EXPECT_EQ(report.reverted_vertices, 1);
  EXPECT_EQ(report.partway_vertices, 1);
  EXPECT_EQ(report.moved_vertices, 7);
  EXPECT_EQ(report.folded_faces, 0);
  const Eigen::Vector3d partway = inner + 7.0 / 16.0 * (closest_point_on_primitive(ball, inner) - inner);
  EXPECT_LT((eig(m.vert[2].cP()) - partway).norm(), tolerance<M>(1.0));
  EXPECT_EQ(eig(m.vert[0].cP()), s.points[0]);
  EXPECT_EQ(eig(m.vert[1].cP()), s.points[1]);
}

// The inner vertex of a fan with a third neighbour below: its projection flips a face, and so does its step
// along the sphere, but the mean of its neighbours folds none, so it stops there instead of going back to where it
// was (the repair is off, so that the hold-back alone is tested), then goes part of the way from there towards
// the sphere. Its neighbours stay on the sphere.
TYPED_TEST(SnapSegmentsTest, FlippingVertexFallsBackBetweenItsNeighbours)
{
  using M = TypeParam;
  Soup s;
  const Eigen::Vector3d below = Eigen::Vector3d(0.6, 0.6, -0.8).normalized();
  s.points = {{1, 0, 0}, {0, 1, 0}, {below.x(), below.y(), below.z()}, {0.3, 0.3, -0.01}};
  s.triangles = {{3, 0, 1}, {3, 1, 2}, {3, 2, 0}};
  s.labels = {0, 0, 0};
  const Primitive ball = unit_ball();
  SnapOptions options;
  options.repair_folds = false;
  ASSERT_TRUE(flips_without_guard<M>(s, ball, options)) << "the setup must flip without the guard";

  M m;
  build_mesh(m, s);
  std::vector<Eigen::Vector3d> normals;
  for (int f = 0; f < 3; ++f)
    normals.push_back(face_normal(m, f));
  options.prevent_flips = true;
  const SnapReport report = snap_segments(m, s.labels, {ball}, options);
  for (int f = 0; f < 3; ++f)
    EXPECT_GT(face_normal(m, f).dot(normals[size_t(f)]), 0) << "face " << f;
  EXPECT_EQ(report.partway_vertices, 1);
  EXPECT_EQ(report.folded_faces, 0);
  for (int v = 0; v < 3; ++v)
    EXPECT_LT(std::abs(signed_distance_to_primitive(ball, eig(m.vert[size_t(v)].cP()))), tolerance<M>(1.0))
        << "vertex " << v;
  // On the way from the mean of its neighbours to the sphere, strictly past the mean and short of the sphere.
  const Eigen::Vector3d mean = (eig(m.vert[0].cP()) + eig(m.vert[1].cP()) + eig(m.vert[2].cP())) / 3;
  const Eigen::Vector3d way = closest_point_on_primitive(ball, mean) - mean;
  const Eigen::Vector3d centre = eig(m.vert[3].cP());
  const double t = (centre - mean).dot(way) / way.squaredNorm();
  EXPECT_LT((centre - (mean + t * way)).norm(), tolerance<M>(10.0));
  EXPECT_GT(t, 0.0);
  EXPECT_LT(t, 1.0);
}

// Vertices of unsnapped segments only are untouched; their boundary with a snapped segment is snapped.
TYPED_TEST(SnapSegmentsTest, UnsnappedSegmentsUntouched)
{
  using M = TypeParam;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  Soup s = make_tube({0, 0, 0}, {0, 0, 1}, 8.0, 32, 16, [&](double, double) { return 4.8 + noise(rng); });
  const int around = 32, along = 16;
  for (size_t f = 0; f < s.triangles.size(); ++f)
    s.labels[f] = static_cast<int>(f) / (2 * around) < along / 2 ? 0 : 1;
  M m;
  build_mesh(m, s);
  std::vector<Eigen::Vector3d> before;
  for (const auto& v : m.vert)
    before.push_back(eig(v.cP()));
  const Primitive cyl = make_cylinder({0, 0, 0}, {0, 0, 1}, 5.0);
  const SnapReport report = snap_segments(m, s.labels, {cyl, std::nullopt});
  EXPECT_EQ(report.moved_vertices, (along / 2 + 1) * around);
  for (size_t v = 0; v < m.vert.size(); ++v) {
    const int ring = static_cast<int>(v) / around;
    if (ring > along / 2) {
      EXPECT_EQ(eig(m.vert[v].cP()), before[v]);
    } else {
      EXPECT_LT(std::abs(signed_distance_to_primitive(cyl, eig(m.vert[v].cP()))), tolerance<M>(10.0));
    }
  }
}

// NaN primitives are not snapped to; a NaN vertex stays as it is and does not spoil its neighbours;
// missing or out-of-range labels mean "no segment"; an empty mesh is fine.
TYPED_TEST(SnapSegmentsTest, BadInputWritesNoNaN)
{
  using M = TypeParam;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Soup s = make_tube({0, 0, 0}, {0, 0, 1}, 8.0, 32, 8, [](double, double) { return 4.8; });

  M m;
  build_mesh(m, s);
  std::vector<Eigen::Vector3d> before;
  for (const auto& v : m.vert)
    before.push_back(eig(v.cP()));
  Primitive broken = make_cylinder({0, 0, 0}, {0, 0, 1}, 5.0);
  broken.radius = nan;
  SnapReport report = snap_segments(m, s.labels, {broken});
  EXPECT_EQ(report.moved_vertices, 0);
  for (size_t v = 0; v < m.vert.size(); ++v)
    EXPECT_EQ(eig(m.vert[v].cP()), before[v]);

  const Primitive cyl = make_cylinder({0, 0, 0}, {0, 0, 1}, 5.0);
  m.vert[40].P()[0] = typename M::ScalarType(nan);
  report = snap_segments(m, s.labels, {cyl});
  EXPECT_EQ(report.moved_vertices, static_cast<int>(m.vert.size()) - 1);
  EXPECT_TRUE(std::isnan(double(m.vert[40].cP()[0])));
  for (size_t v = 0; v < m.vert.size(); ++v) {
    if (v != 40) {
      EXPECT_LT(std::abs(signed_distance_to_primitive(cyl, eig(m.vert[v].cP()))), tolerance<M>(10.0));
    }
  }
  EXPECT_TRUE(std::isfinite(report.mean_displacement));
  EXPECT_TRUE(std::isfinite(report.max_displacement));

  // Labels too short and out of range: only the labelled faces' vertices (ring 0 and 1) may move.
  M partial;
  build_mesh(partial, s);
  std::vector<int> labels(static_cast<size_t>(2 * 32), 0);
  labels[0] = 7;
  report = snap_segments(partial, labels, {cyl});
  EXPECT_EQ(report.moved_vertices, 2 * 32);

  M empty;
  report = snap_segments(empty, {}, {cyl});
  EXPECT_EQ(report.moved_vertices, 0);
  EXPECT_EQ(report.mean_displacement, 0.0);
}

// A 10 x 10 x 4 plate with a through hole of radius 2, chamfered and noisy: six planes and a cylinder.
// The plate's 8 corners, its edges and both rims of the hole must come out sharp, with no face flipped.
TYPED_TEST(SnapSegmentsTest, PlateWithHoleBecomesSharp)
{
  using M = TypeParam;
  const plate_fixture::PlateWithHole plate = plate_fixture::make_plate_with_hole(0.02);
  const Soup& s = plate.soup;
  const std::vector<int>& kind = plate.kind;
  const std::vector<std::optional<Primitive>>& primitives = plate.primitives;
  const double half = plate.half, thick = plate.thick;
  M m;
  build_mesh(m, s);
  const SnapReport report = snap_segments(m, s.labels, primitives);
  EXPECT_EQ(report.corner_vertices, 8);
  EXPECT_EQ(report.reverted_vertices, 0);
  // Every vertex lies on the primitive of each of its faces: on two at edges, three at corners.
  std::vector<std::vector<int>> labels_of_vertex(m.vert.size());
  for (size_t f = 0; f < s.triangles.size(); ++f)
    for (int v : s.triangles[f])
      labels_of_vertex[static_cast<size_t>(v)].push_back(s.labels[f]);
  for (size_t v = 0; v < m.vert.size(); ++v)
    for (int label : labels_of_vertex[v])
      EXPECT_LT(std::abs(signed_distance_to_primitive(*primitives[static_cast<size_t>(label)], eig(m.vert[v].cP()))),
                tolerance<M>(10.0))
          << "vertex " << v << " of kind " << kind[v] << ", label " << label;
  for (size_t v = 0; v < m.vert.size(); ++v)
    if (kind[v] == 4) {
      const Eigen::Vector3d x = eig(m.vert[v].cP());
      EXPECT_NEAR(std::abs(x.x()), half, 1e-4);
      EXPECT_NEAR(std::abs(x.y()), half, 1e-4);
      EXPECT_TRUE(std::abs(x.z()) < 1e-4 || std::abs(x.z() - thick) < 1e-4);
    }
  // No face flipped: each faces its surface's outside (into the hole on the hole's wall).
  for (size_t f = 0; f < m.face.size(); ++f) {
    const int label = s.labels[f];
    const Eigen::Vector3d centre = (eig(m.face[f].cP(0)) + eig(m.face[f].cP(1)) + eig(m.face[f].cP(2))) / 3;
    const Eigen::Vector3d expected = label == 2 ? Eigen::Vector3d(-centre.x(), -centre.y(), 0).normalized()
                                                : primitives[static_cast<size_t>(label)]->axis;
    EXPECT_GT(face_normal(m, f).normalized().dot(expected), 0.9) << "face " << f << " label " << label;
  }
}

// The edit tool's case: the hole of the plate widened from radius 2 to `radius` and only the hole snapped.
// The rim moves out onto the new wall; the top and bottom faces it would fold over are repaired by sliding
// their vertices outwards on the scan's surface, so nothing is held back and no step is left at the rim.
// Without the repair the rim is held back at the old radius. On a noisy plate a slid vertex stays within the
// noise of its plane (sliding in its own tangent plane, which the noise tilts, lifted some by 0.1).
template <class M>
void expect_widened_hole_repaired(double radius, double noise = 0.0)
{
  SCOPED_TRACE(radius);
  SCOPED_TRACE(noise);
  const plate_fixture::PlateWithHole plate = plate_fixture::make_plate_with_hole(noise);
  Primitive wider = *plate.primitives[2];
  wider.radius = radius;
  std::vector<std::optional<Primitive>> only_hole(plate.primitives.size());
  only_hole[2] = wider;

  M held;
  build_mesh(held, plate.soup);
  SnapOptions no_repair;
  no_repair.repair_folds = false;
  const SnapReport held_report = snap_segments(held, plate.soup.labels, only_hole, no_repair);
  EXPECT_GT(held_report.reverted_vertices, 64) << "the setup must fold the planes without the repair";

  M m;
  build_mesh(m, plate.soup);
  const SnapReport report = snap_segments(m, plate.soup.labels, only_hole);
  EXPECT_EQ(report.reverted_vertices, 0);
  EXPECT_EQ(report.folded_faces, 0);
  EXPECT_GT(report.repaired_vertices, 64);
  std::vector<char> on_wall(m.vert.size(), 0), on_top_or_bottom(m.vert.size(), 0);
  for (size_t f = 0; f < m.face.size(); ++f)
    for (int v : plate.soup.triangles[f]) {
      on_wall[size_t(v)] |= plate.soup.labels[f] == 2;
      on_top_or_bottom[size_t(v)] |= plate.soup.labels[f] <= 1;
    }
  for (size_t v = 0; v < m.vert.size(); ++v) {
    const Eigen::Vector3d before = plate.soup.points[v], x = eig(m.vert[v].cP());
    if (on_wall[v]) {  // on the new wall (the rims at their old height), inside the plate
      EXPECT_NEAR(std::hypot(x.x(), x.y()), radius, 1e-4) << "wall vertex " << v;
      EXPECT_TRUE(x.z() > 0 && x.z() < plate.thick) << "wall vertex " << v;
    }
    if (plate.kind[v] == 1) {  // the rims keep their height
      EXPECT_NEAR(x.z(), before.z(), 1e-4) << "rim vertex " << v;
    } else if (!on_wall[v] && plate.kind[v] == 0) {  // inside the top, bottom and sides: on the scan's surface
      if (on_top_or_bottom[v])
        EXPECT_LE(std::abs(x.z() - (before.z() > plate.thick / 2 ? plate.thick : 0.0)), noise + 1e-4) << "vertex " << v;
      else
        EXPECT_LT((x - before).norm(), 1e-5) << "side vertex " << v;
    } else if (plate.kind[v] >= 2) {  // the plate's outer border stays
      EXPECT_LT((x - before).norm(), 1e-5) << "outer vertex " << v;
    }
  }
  for (size_t f = 0; f < m.face.size(); ++f) {
    const Eigen::Vector3d a = plate.soup.points[size_t(plate.soup.triangles[f][0])];
    const Eigen::Vector3d before = (plate.soup.points[size_t(plate.soup.triangles[f][1])] - a)
                                       .cross(plate.soup.points[size_t(plate.soup.triangles[f][2])] - a);
    EXPECT_GT(face_normal(m, f).dot(before), 0) << "face " << f;
  }
}

TYPED_TEST(SnapSegmentsTest, WidenedHoleRepairsFoldsInsteadOfHoldingBack)
{
  // 2 -> 3 reaches past the rims' first ring; 2 -> 3.8 past four, where a region grown only around the
  // faces still folded stalled against the pinned rims and held them back (256 vertices).
  expect_widened_hole_repaired<TypeParam>(3.0);
  expect_widened_hole_repaired<TypeParam>(3.8);
  expect_widened_hole_repaired<TypeParam>(3.8, 0.02);
}

// The log line says how many border vertices reached their edge or corner, and says nothing of borders when the
// snap had none (one segment alone).
TEST(DescribeSnapReport, GivesTheBorderShareOnlyWhenThereIsABorder)
{
  SnapReport r;
  r.moved_vertices = 1200;
  r.edge_vertices = 64;
  r.corner_vertices = 8;
  r.border_vertices = 80;
  r.repaired_vertices = 96;
  EXPECT_EQ(describe_snap_report(r).rfind("1200 vertices moved (64 onto edges and 8 onto corners of the 80 on borders "
                                          "between segments; 96 slid along their surfaces",
                                          0),
            0u)
      << describe_snap_report(r);
  EXPECT_EQ(describe_snap_report(r).find("part of the way"), std::string::npos) << describe_snap_report(r);
  r.reverted_vertices = 4;
  r.partway_vertices = 3;
  EXPECT_NE(describe_snap_report(r).find("4 held back where that was not enough, 3 of them part of the way), mean"),
            std::string::npos)
      << describe_snap_report(r);
  r.reverted_vertices = r.partway_vertices = 0;
  r.edge_vertices = r.corner_vertices = r.border_vertices = 0;
  r.folded_faces = 3;
  r.folded_area = 0.5;
  const std::string alone = describe_snap_report(r);
  EXPECT_EQ(alone.rfind("1200 vertices moved (96 slid along", 0), 0u) << alone;
  EXPECT_EQ(alone.find("border"), std::string::npos) << alone;
  EXPECT_NE(alone.find("; 3 triangles left folded (area 0.5)"), std::string::npos) << alone;
}
