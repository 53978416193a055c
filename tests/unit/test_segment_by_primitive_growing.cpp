// Unit tests of segment_by_primitive_growing: a noisy extruded profile (plane, cylindrical fillet, plane,
// rounded corner, plane) is split into its CAD faces with the rounded corner split between its two planes
// by nearest surface; a noisy sphere is one segment; bad input does not crash. On the tests' mesh type and
// MeshLab's CMeshO (float coordinates).
#include "common/base/constants.h"
#include "test_mesh.h"

#include "common/mesh/face_adjacency.h"
#include "common/segment/relax_region_borders.h"
#include "common/segment/segment_by_primitive_growing.h"

#include "meshlab_test_mesh.h"
#include "test_fit_data.h"
#include <gtest/gtest.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/create/platonic.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace primitive_edit;

namespace {

template <class M>
typename M::CoordType grow_coord(double x, double y, double z)
{
  using S = typename M::ScalarType;
  return typename M::CoordType(S(x), S(y), S(z));
}

// A 2D profile in (x, z), by arc length: plane z = 0 for x in [-6, 0]; a convex cylindrical fillet of
// radius 2 around (0, -2) down to (2, -2); the wall x = 2 down to z = -8; a corner rounded with radius
// 0.3 (the CAD corner is sharp: a blurred scan edge); the floor z = -8 for x in [2, 8].
struct Profile
{
  static constexpr double kRound = 0.3;
  double length() const { return 6.0 + kPi + (6.0 - kRound) + 0.5 * kPi * kRound + (6.0 - kRound); }
  // Point and outward normal at arc length s.
  void at(double s, double& x, double& z, double& nx, double& nz) const
  {
    if (s < 6.0) {
      x = s - 6.0, z = 0.0, nx = 0.0, nz = 1.0;
      return;
    }
    s -= 6.0;
    if (s < kPi) {
      const double a = s / 2.0; // angle from the top of the fillet
      nx = std::sin(a), nz = std::cos(a), x = 2.0 * nx, z = -2.0 + 2.0 * nz;
      return;
    }
    s -= kPi;
    if (s < 6.0 - kRound) {
      x = 2.0, z = -2.0 - s, nx = 1.0, nz = 0.0;
      return;
    }
    s -= 6.0 - kRound;
    if (s < 0.5 * kPi * kRound) {
      // Concave corner: centre (2 + r, -8 + r), normal turning from +x to +z.
      const double a = s / kRound;
      nx = std::cos(a), nz = std::sin(a);
      x = 2.0 + kRound - kRound * nx, z = -8.0 + kRound - kRound * nz;
      return;
    }
    s -= 0.5 * kPi * kRound;
    x = 2.0 + kRound + s, z = -8.0, nx = 0.0, nz = 1.0;
  }
  // Index of the nearest CAD face to (x, z): 0 top plane, 1 fillet, 2 wall, 3 floor (the ground truth of a
  // scan, like bench/data's truth files).
  static int nearest_face(double x, double z)
  {
    const double d_top = x <= 0 ? std::abs(z) : std::hypot(x, z);
    const double rho = std::hypot(x, z + 2.0);
    const bool in_fillet = x >= 0 && z >= -2.0;
    const double d_fillet = in_fillet ? std::abs(rho - 2.0) : std::numeric_limits<double>::infinity();
    const double d_wall = z <= -2.0 && z >= -8.0 ? std::abs(x - 2.0) : std::hypot(x - 2.0, std::min(std::abs(z + 2.0), std::abs(z + 8.0)));
    const double d_floor = x >= 2.0 ? std::abs(z + 8.0) : std::hypot(x - 2.0, z + 8.0);
    const double d[4] = {d_top, d_fillet, d_wall, d_floor};
    return int(std::min_element(d, d + 4) - d);
  }
};

// The profile extruded along y in [0, 8], grid step h, vertices moved along the normal by Gaussian noise;
// truth[f] = nearest CAD face of each triangle's centroid.
template <class M>
void make_profile_scan(M& m, double h, double noise, std::vector<int>& truth)
{
  m.Clear();
  const Profile profile;
  const int nu = int(std::ceil(profile.length() / h));
  const int nv = int(std::ceil(8.0 / h));
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss(0.0, noise);
  auto vi = vcg::tri::Allocator<M>::AddVertices(m, size_t(nu + 1) * size_t(nv + 1));
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j, ++vi) {
      double x, z, nx, nz;
      profile.at(profile.length() * i / nu, x, z, nx, nz);
      const double e = noise > 0 ? gauss(rng) : 0.0;
      vi->P() = grow_coord<M>(x + e * nx, 8.0 * j / nv, z + e * nz);
    }
  truth.clear();
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      auto* a = &m.vert[size_t(i) * size_t(nv + 1) + size_t(j)];
      auto* b = &m.vert[size_t(i + 1) * size_t(nv + 1) + size_t(j)];
      auto* c = &m.vert[size_t(i + 1) * size_t(nv + 1) + size_t(j + 1)];
      auto* d = &m.vert[size_t(i) * size_t(nv + 1) + size_t(j + 1)];
      vcg::tri::Allocator<M>::AddFace(m, a, c, b);
      vcg::tri::Allocator<M>::AddFace(m, a, d, c);
    }
  for (const auto& f : m.face) {
    const auto c = (f.cP(0) + f.cP(1) + f.cP(2)) / 3;
    truth.push_back(Profile::nearest_face(double(c[0]), double(c[2])));
  }
}

// Share of faces whose segment's majority truth label is their own truth label.
double labelled_share(const std::vector<int>& seg, const std::vector<int>& truth, int K)
{
  std::vector<std::map<int, int>> votes(size_t(std::max(K, 0)));
  for (size_t f = 0; f < seg.size(); ++f)
    ++votes[size_t(seg[f])][truth[f]];
  std::vector<int> label(size_t(std::max(K, 0)), -1);
  for (int k = 0; k < K; ++k) {
    int best = 0;
    for (const auto& [t, n] : votes[size_t(k)])
      if (n > best)
        best = n, label[size_t(k)] = t;
  }
  size_t ok = 0;
  for (size_t f = 0; f < seg.size(); ++f)
    ok += label[size_t(seg[f])] == truth[f] ? 1 : 0;
  return seg.empty() ? 0.0 : double(ok) / double(seg.size());
}

template <class M>
void expect_dense_ids(const M& m, const std::vector<int>& seg, int K)
{
  ASSERT_EQ(seg.size(), m.face.size());
  std::vector<char> used(size_t(std::max(K, 0)), 0);
  for (size_t f = 0; f < seg.size(); ++f) {
    if (m.face[f].IsD()) {
      EXPECT_EQ(seg[f], -1);
      continue;
    }
    ASSERT_GE(seg[f], 0);
    ASSERT_LT(seg[f], K);
    used[size_t(seg[f])] = 1;
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 1), K);
}

template <class M>
class PrimitiveGrowingTest : public ::testing::Test {};
using GrowMeshTypes = ::testing::Types<test_mesh::TMesh, test_mesh::MeshLabMesh>;
TYPED_TEST_SUITE(PrimitiveGrowingTest, GrowMeshTypes);

TYPED_TEST(PrimitiveGrowingTest, NoisyProfileGivesOneSegmentPerCadFace)
{
  TypeParam m;
  std::vector<int> truth;
  make_profile_scan(m, 0.12, 0.02, truth);
  std::vector<int> seg;
  SegmentByPrimitiveGrowingReport report;
  const int K = segment_by_primitive_growing(m, SegmentByPrimitiveGrowingParams(), seg, &report);
  expect_dense_ids(m, seg, K);
  EXPECT_EQ(K, 4);
  EXPECT_GT(report.tolerance, 0.0);
  EXPECT_GT(labelled_share(seg, truth, K), 0.97);
  // The fillet is recognised as a cylinder of radius 2 along y, the rest as planes.
  ASSERT_EQ(report.primitive_of_segment.size(), size_t(K));
  int cylinders = 0, planes = 0;
  for (const auto& p : report.primitive_of_segment) {
    ASSERT_TRUE(p.has_value());
    if (p->type == PrimitiveType::Cylinder) {
      ++cylinders;
      EXPECT_NEAR(p->radius, 2.0, 0.1);
      EXPECT_GT(std::abs(p->axis.y()), 0.99);
    }
    planes += p->type == PrimitiveType::Plane ? 1 : 0;
  }
  EXPECT_EQ(cylinders, 1);
  EXPECT_EQ(planes, 3);
}

TYPED_TEST(PrimitiveGrowingTest, RoundedCornerIsSplitBetweenItsPlanesByNearestSurface)
{
  TypeParam m;
  std::vector<int> truth;
  make_profile_scan(m, 0.12, 0.02, truth);
  std::vector<int> seg;
  const int K = segment_by_primitive_growing(m, SegmentByPrimitiveGrowingParams(), seg);
  ASSERT_GE(K, 1);
  // The faces of the rounded corner (the scan's blurred edge between wall and floor): each goes to the
  // segment that holds most of its nearest CAD face.
  std::vector<std::map<int, int>> votes(static_cast<size_t>(K));
  for (size_t f = 0; f < seg.size(); ++f)
    ++votes[size_t(seg[f])][truth[f]];
  auto majority = [&](int k) {
    int best = -1, count = 0;
    for (const auto& [t, n] : votes[size_t(k)])
      if (n > count)
        best = t, count = n;
    return best;
  };
  int corner = 0, right = 0;
  for (size_t f = 0; f < m.face.size(); ++f) {
    const auto c = (m.face[f].cP(0) + m.face[f].cP(1) + m.face[f].cP(2)) / 3;
    const double x = double(c[0]), z = double(c[2]);
    if (x < 2.0 + Profile::kRound && z < -8.0 + Profile::kRound && x > 1.95 && z > -8.05) {
      ++corner;
      right += majority(seg[f]) == truth[f] ? 1 : 0;
    }
  }
  ASSERT_GT(corner, 20);
  EXPECT_GE(double(right) / corner, 0.85);
}

TYPED_TEST(PrimitiveGrowingTest, NoisySphereIsOneSegment)
{
  TypeParam m;
  vcg::tri::Sphere(m, 5);
  std::mt19937 rng(3);
  std::normal_distribution<double> gauss(0.0, 0.003);
  for (auto& v : m.vert) {
    const auto p = v.P();
    const double s = 1.0 + gauss(rng);
    v.P() = grow_coord<TypeParam>(double(p[0]) * s, double(p[1]) * s, double(p[2]) * s);
  }
  std::vector<int> seg;
  SegmentByPrimitiveGrowingReport report;
  const int K = segment_by_primitive_growing(m, SegmentByPrimitiveGrowingParams(), seg, &report);
  expect_dense_ids(m, seg, K);
  EXPECT_EQ(K, 1);
  ASSERT_EQ(report.primitive_of_segment.size(), 1u);
  ASSERT_TRUE(report.primitive_of_segment[0].has_value());
  EXPECT_EQ(report.primitive_of_segment[0]->type, PrimitiveType::Sphere);
  EXPECT_NEAR(report.primitive_of_segment[0]->radius, 1.0, 0.02);
}

// A 20 x 20 plane (z = 0, x in [-20, 0]) meeting an 8-high wall (x = 0.5) through an edge rounded with
// radius 0.5, the whole sheet displaced along its normal by a smooth random waviness: 12 plane waves of
// wavelength 4-8 over the unrolled sheet, standard deviation `amplitude` (a rough casting's CT scan).
// Triangles of about h; truth: 0 = plane (and the first half of the round), 1 = wall.
template <class M>
void make_wavy_corner(M& m, double h, double amplitude, std::vector<int>& truth)
{
  const double round = 0.5, arc = 0.5 * kPi * round, length = 20.0 + arc + 8.0;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  constexpr int kWaves = 12;
  double kx[kWaves], ky[kWaves], phase[kWaves];
  for (int w = 0; w < kWaves; ++w) {
    const double k = 2.0 * kPi / (4.0 + 4.0 * uniform(rng)), dir = 2.0 * kPi * uniform(rng);
    kx[w] = k * std::cos(dir), ky[w] = k * std::sin(dir), phase[w] = 2.0 * kPi * uniform(rng);
  }
  auto displacement = [&](double u, double y) {
    double d = 0;
    for (int w = 0; w < kWaves; ++w)
      d += std::sin(kx[w] * u + ky[w] * y + phase[w]);
    return amplitude * d * std::sqrt(2.0 / kWaves);
  };
  const int nu = int(std::ceil(length / h)), nv = int(std::ceil(20.0 / h));
  auto vi = vcg::tri::Allocator<M>::AddVertices(m, size_t(nu + 1) * size_t(nv + 1));
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j, ++vi) {
      const double u = length * i / nu, y = 20.0 * j / nv;
      double x, z, nx, nz;
      if (u < 20.0) {
        x = u - 20.0, z = 0.0, nx = 0.0, nz = 1.0;
      } else if (u < 20.0 + arc) {
        const double a = (u - 20.0) / round;
        nx = std::sin(a), nz = std::cos(a), x = round * nx, z = -round + round * nz;
      } else {
        x = round, z = -round - (u - 20.0 - arc), nx = 1.0, nz = 0.0;
      }
      const double e = displacement(u, y);
      vi->P() = grow_coord<M>(x + e * nx, y, z + e * nz);
    }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      auto* a = &m.vert[size_t(i) * size_t(nv + 1) + size_t(j)];
      auto* b = &m.vert[size_t(i + 1) * size_t(nv + 1) + size_t(j)];
      auto* c = &m.vert[size_t(i + 1) * size_t(nv + 1) + size_t(j + 1)];
      auto* d = &m.vert[size_t(i) * size_t(nv + 1) + size_t(j + 1)];
      vcg::tri::Allocator<M>::AddFace(m, a, c, b);
      vcg::tri::Allocator<M>::AddFace(m, a, d, c);
    }
  truth.clear();
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < 2 * nv; ++j)
      truth.push_back(length * (i + 0.5) / nu < 20.0 + 0.5 * arc ? 0 : 1);
}

TYPED_TEST(PrimitiveGrowingTest, WavyPlaneAndWallGiveTwoSegments)
{
  TypeParam m;
  std::vector<int> truth;
  make_wavy_corner(m, 0.25, 0.5, truth);
  // The tolerance a CT scan of this roughness gets (1.6 standard deviations: the bracket scan's ratio): the
  // distance and normal tests miss faces all over both surfaces and local fits tilt with the waves, yet
  // each surface is one segment. (This surface is too small for the automatic roughness estimate to see
  // waves of this length.) Growth alone: the carve reads the 0.5 mm round under these waves as a 1.6 mm fillet
  // (carve_edge_blends.h, Limits).
  SegmentByPrimitiveGrowingParams params;
  params.tolerance = 0.8;
  params.carve_blends = false;
  std::vector<int> seg;
  SegmentByPrimitiveGrowingReport report;
  const int K = segment_by_primitive_growing(m, params, seg, &report);
  expect_dense_ids(m, seg, K);
  EXPECT_EQ(K, 2);
  EXPECT_GT(labelled_share(seg, truth, K), 0.95);
  for (const auto& p : report.primitive_of_segment) {
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->type, PrimitiveType::Plane) << "radius " << p->radius;
  }
}

TYPED_TEST(PrimitiveGrowingTest, SameSegmentsOnEveryThreadCount)
{
  // The wavy surfaces grow many regions that merging joins; its pair tests run a window per thread count.
  TypeParam m;
  std::vector<int> truth;
  make_wavy_corner(m, 0.25, 0.5, truth);
  SegmentByPrimitiveGrowingParams params;
  params.tolerance = 0.8;
  params.threads = 1;
  std::vector<int> one;
  SegmentByPrimitiveGrowingReport one_report;
  const int K = segment_by_primitive_growing(m, params, one, &one_report);
  ASSERT_GT(one_report.grown_regions, K + 2) << "too few merges to compare";
  for (int threads : {2, 3}) {
    params.threads = threads;
    std::vector<int> seg;
    SegmentByPrimitiveGrowingReport report;
    EXPECT_EQ(segment_by_primitive_growing(m, params, seg, &report), K) << threads << " threads";
    EXPECT_EQ(seg, one) << threads << " threads";
    ASSERT_EQ(report.primitive_of_segment.size(), one_report.primitive_of_segment.size());
    for (std::size_t k = 0; k < report.primitive_of_segment.size(); ++k) {
      ASSERT_EQ(report.primitive_of_segment[k].has_value(), one_report.primitive_of_segment[k].has_value());
      if (report.primitive_of_segment[k]) {
        EXPECT_EQ(report.primitive_of_segment[k]->origin, one_report.primitive_of_segment[k]->origin);
        EXPECT_EQ(report.primitive_of_segment[k]->axis, one_report.primitive_of_segment[k]->axis);
      }
    }
  }
}

TYPED_TEST(PrimitiveGrowingTest, BadInputDoesNotCrash)
{
  std::vector<int> seg{1, 2, 3};
  TypeParam empty;
  EXPECT_EQ(segment_by_primitive_growing(empty, SegmentByPrimitiveGrowingParams(), seg), 0);
  EXPECT_TRUE(seg.empty());

  TypeParam m;
  std::vector<int> truth;
  make_profile_scan(m, 0.3, 0.0, truth);
  EXPECT_EQ(segment_by_primitive_growing(m, FaceAdjacency{}, SegmentByPrimitiveGrowingParams(), seg), 0)
      << "adjacency of another mesh";

  // A repeated-vertex face, a NaN vertex, a non-manifold fin on an edge, a deleted face.
  auto* v = &m.vert[0];
  auto degenerate = vcg::tri::Allocator<TypeParam>::AddFaces(m, 1);
  degenerate->V(0) = v + 0;
  degenerate->V(1) = v + 0;
  degenerate->V(2) = v + 1;
  auto vi = vcg::tri::Allocator<TypeParam>::AddVertices(m, 2);
  v = &m.vert[0];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vi[0].P() = grow_coord<TypeParam>(nan, 0.0, nan);
  vi[1].P() = grow_coord<TypeParam>(-5.0, 1.0, 3.0);
  vcg::tri::Allocator<TypeParam>::AddFace(m, v + 0, v + 1, &*vi);
  vcg::tri::Allocator<TypeParam>::AddFace(m, v + 0, v + 1, &*(vi + 1));
  vcg::tri::Allocator<TypeParam>::DeleteFace(m, m.face[3]);

  SegmentByPrimitiveGrowingReport report;
  for (const SegmentByPrimitiveGrowingParams& params :
       {SegmentByPrimitiveGrowingParams(), SegmentByPrimitiveGrowingParams{nan, nan, -5, -1, -2},
        SegmentByPrimitiveGrowingParams{1e-9, 89.0, 3, 1, 0}}) {
    const int K = segment_by_primitive_growing(m, params, seg, &report);
    EXPECT_GE(K, 1);
    expect_dense_ids(m, seg, K);
    EXPECT_TRUE(std::isfinite(report.tolerance));
    EXPECT_EQ(report.primitive_of_segment.size(), size_t(K));
    for (const auto& p : report.primitive_of_segment) {
      if (p) {
        EXPECT_TRUE(primitive_is_valid(*p));
      }
    }
  }

  // A lone triangle and a mesh whose vertices all coincide: no primitive, still labelled.
  TypeParam tiny;
  vcg::tri::Allocator<TypeParam>::AddVertices(tiny, 3);
  tiny.vert[1].P() = grow_coord<TypeParam>(1, 0, 0);
  tiny.vert[2].P() = grow_coord<TypeParam>(0, 1, 0);
  vcg::tri::Allocator<TypeParam>::AddFace(tiny, &tiny.vert[0], &tiny.vert[1], &tiny.vert[2]);
  EXPECT_EQ(segment_by_primitive_growing(tiny, SegmentByPrimitiveGrowingParams(), seg), 1);
  for (auto& p : tiny.vert)
    p.P() = grow_coord<TypeParam>(1, 1, 1);
  EXPECT_EQ(segment_by_primitive_growing(tiny, SegmentByPrimitiveGrowingParams(), seg), 1);
}

// The roughness comes from the mesh attribute, not from the user: one that is not a positive number is unknown
// and estimated, never an infinite or NaN tolerance (found by fuzz_segment).
TYPED_TEST(PrimitiveGrowingTest, RoughnessNotFiniteIsEstimated)
{
  TypeParam m;
  std::vector<int> truth;
  make_profile_scan(m, 0.12, 0.02, truth);
  std::vector<int> estimated, seg;
  SegmentByPrimitiveGrowingReport expected, report;
  const int K = segment_by_primitive_growing(m, SegmentByPrimitiveGrowingParams(), estimated, &expected);
  ASSERT_GT(expected.roughness, 0.0);
  for (double broken : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    SegmentByPrimitiveGrowingParams params;
    params.roughness = broken;
    EXPECT_EQ(segment_by_primitive_growing(m, params, seg, &report), K) << broken;
    EXPECT_EQ(seg, estimated) << broken;
    EXPECT_EQ(report.roughness, expected.roughness) << broken;
    EXPECT_EQ(report.tolerance, expected.tolerance) << broken;
  }
}

// Out-of-range numbers are refused with the parameter's name, never changed: the segmentation would keep
// within range on its own, so an adapter that skipped this check would silently use another value.
TEST(PrimitiveGrowingParams, OutOfRangeIsRefusedByName)
{
  EXPECT_TRUE(check_primitive_growing_params(SegmentByPrimitiveGrowingParams()).ok());
  auto refusal = [](auto change) {
    SegmentByPrimitiveGrowingParams params;
    change(params);
    return check_primitive_growing_params(params).error;
  };
  EXPECT_NE(refusal([](auto& p) { p.tolerance = std::nan(""); }).find("Tolerance"), std::string::npos);
  EXPECT_NE(refusal([](auto& p) { p.tolerance = -1; }).find("Tolerance"), std::string::npos);
  EXPECT_NE(refusal([](auto& p) { p.normal_angle_deg = 0.5; }).find("Normal Angle"), std::string::npos);
  EXPECT_NE(refusal([](auto& p) { p.normal_angle_deg = 89.5; }).find("not 89.5"), std::string::npos);
  EXPECT_NE(refusal([](auto& p) { p.seed_patch_faces = 7; }).find("Seed Patch Size"), std::string::npos);
  EXPECT_NE(refusal([](auto& p) { p.smoothing_iterations = 1001; }).find("Normal Smoothing Steps"), std::string::npos);
  EXPECT_TRUE(refusal([](auto& p) {
                p.normal_angle_deg = kMaxGrowingNormalAngleDeg;
                p.seed_patch_faces = kMinSeedPatchFaces;
              }).empty());
}

// FaceAgreement skips acos for normals clearly within the angle or beyond twice it; every decision must stay
// the one the angle test alone gives (the distance-widened angle of growing_faces.h).
TEST(FaceAgreement, DecidesAsTheAngleTestAlone)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  GrowingFaces g;
  const int n = 20000;
  for (int f = 0; f < n; ++f) {
    g.centroid.emplace_back(3 * uniform(random), 3 * uniform(random), 0.1 * uniform(random));
    g.normal.push_back(Eigen::Vector3d(uniform(random), uniform(random), 2 * uniform(random)).normalized());
  }
  const Primitive plane = test_fit::make_plane(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  const Primitive sphere = test_fit::make_sphere(Eigen::Vector3d(0, 0, -5), 5);
  for (const double tol : {0.0, 0.02, 0.08})
    for (const double angle_deg : {5.0, 25.0, 50.0, 120.0})
      for (const Primitive& prim : {plane, sphere}) {
        const double angle = radians_from_degrees(angle_deg);
        const FaceAgreement agrees(tol, angle);
        int differ = 0, agreeing = 0;
        for (int f = 0; f < n; ++f) {
          const PrimitiveProjection pr = project_onto_primitive(prim, g.centroid[std::size_t(f)]);
          const double d = std::abs(pr.signed_distance);
          const double c = std::min(1.0, std::abs(pr.normal.dot(g.normal[std::size_t(f)])));
          const bool expected = d <= tol && std::acos(c) <= angle * (2.0 - d / tol);
          differ += agrees(g, prim, f) != expected ? 1 : 0;
          agreeing += expected ? 1 : 0;
        }
        EXPECT_EQ(differ, 0) << "tol " << tol << ", angle " << angle_deg;
        if (tol > 0 && angle_deg < 90) {
          EXPECT_GT(agreeing, 0);
        }
      }
}

// agreeing_share_reaches stops early; its verdict must be the full share's, also at the share itself and one
// step above it.
TEST(AgreeingShareReaches, SameVerdictAsTheFullShare)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  GrowingFaces g;
  std::vector<int> faces;
  for (int f = 0; f < 5000; ++f) {
    g.centroid.emplace_back(3 * uniform(random), 3 * uniform(random), 0.05 * uniform(random));
    g.normal.push_back(Eigen::Vector3d(0.3 * uniform(random), 0.3 * uniform(random), 1).normalized());
    g.area.push_back(0.5 + uniform(random) * 0.4);
    faces.push_back(f);
  }
  const Primitive plane = test_fit::make_plane(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  for (const double tol : {0.01, 0.03, 0.06}) {
    const double angle = radians_from_degrees(10);
    const double share = strided_share(g, plane, faces, tol, angle, faces.size());
    ASSERT_GT(share, 0.05);
    ASSERT_LT(share, 0.99);
    for (const double threshold : {0.0, 0.5 * share, share, std::nextafter(share, 2.0), 0.5 + 0.5 * share, 1.0})
      EXPECT_EQ(agreeing_share_reaches(g, plane, faces, tol, angle, threshold), share >= threshold)
          << "tol " << tol << ", share " << share << ", threshold " << threshold;
  }
  EXPECT_TRUE(agreeing_share_reaches(g, plane, {}, 0.01, 0.1, 0.0));
  EXPECT_FALSE(agreeing_share_reaches(g, plane, {}, 0.01, 0.1, 0.5));
}

// The border relaxation looks again only at faces next to a move; it must end with the labels and the move count
// of passes over every face (the rule it replaced, written out here with the same choice per face).
int relax_looking_at_every_face(const GrowingFaces& g, const FaceAdjacency& adj, const std::vector<Primitive>& prim,
                                double tol, std::vector<int>& label)
{
  int total = 0;
  for (int pass = 0; pass < kRelaxPasses; ++pass) {
    int moved = 0;
    for (int f = 0; f < int(label.size()); ++f) {
      const int best = best_region_for_face(g, adj, prim, tol, label, f);
      if (best != label[std::size_t(f)]) {
        label[std::size_t(f)] = best;
        ++moved;
      }
    }
    total += moved;
    if (moved == 0)
      break;
  }
  return total;
}

TEST(RelaxRegionBorders, MovesWhatAPassOverEveryFaceMoves)
{
  test_mesh::TMesh m;
  vcg::tri::Sphere(m, 6); // 81920 faces: the border faces are found over two ranges of kFacesPerThread
  const FaceAdjacency adj = build_face_adjacency(m);
  const GrowingFaces g = growing_faces(m, adj, 0);
  const std::vector<Primitive> prim = {
      test_fit::make_plane(Eigen::Vector3d(0, 0, 0.5), Eigen::Vector3d::UnitZ()),
      test_fit::make_plane(Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitX()),
      test_fit::make_sphere(Eigen::Vector3d::Zero(), 1.0)};
  std::mt19937 random(3);
  std::uniform_int_distribution<int> pick(-1, 3); // -1: no region; 3: a component beyond the regions
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<int> label(m.face.size());
    for (int& l : label)
      l = pick(random);
    std::vector<int> expected = label;
    const int expected_moves = relax_looking_at_every_face(g, adj, prim, 0.1, expected);
    ASSERT_GT(expected_moves, int(label.size()) / 10) << "a trial that moves little tests little";
    for (int threads : {1, 2}) {
      std::vector<int> relaxed = label;
      EXPECT_EQ(relax_region_borders(g, adj, prim, 0.1, relaxed, threads), expected_moves) << "trial " << trial;
      EXPECT_EQ(relaxed, expected) << "trial " << trial << ", " << threads << " threads";
    }
  }
}

// The floor z = 0 (x <= -c) and the wall x = 0 (z >= c) joined by a 45-degree chamfer of setback c, extruded
// along y in [0, 4] with grid step h; exact.
void make_chamfered_corner(test_mesh::TMesh& m, double c, double h)
{
  const double chamfer = c * std::sqrt(2.0), length = (6.0 - c) + chamfer + (6.0 - c);
  auto at = [&](double s) -> Eigen::Vector2d {
    if (s <= 6.0 - c)
      return Eigen::Vector2d(s - 6.0, 0.0);
    if (s <= 6.0 - c + chamfer)
      return Eigen::Vector2d(-c, 0.0) + (s - (6.0 - c)) / chamfer * Eigen::Vector2d(c, c);
    return Eigen::Vector2d(0.0, c + (s - (6.0 - c + chamfer)));
  };
  const int nu = int(std::ceil(length / h)), nv = int(std::ceil(4.0 / h));
  auto vi = vcg::tri::Allocator<test_mesh::TMesh>::AddVertices(m, size_t(nu + 1) * size_t(nv + 1));
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j, ++vi) {
      const Eigen::Vector2d q = at(length * i / nu);
      vi->P() = test_mesh::TMesh::CoordType(q[0], 4.0 * j / nv, q[1]);
    }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      auto* a = &m.vert[size_t(i) * size_t(nv + 1) + size_t(j)];
      auto* b = &m.vert[size_t(i + 1) * size_t(nv + 1) + size_t(j)];
      auto* d = &m.vert[size_t(i) * size_t(nv + 1) + size_t(j + 1)];
      auto* e = &m.vert[size_t(i + 1) * size_t(nv + 1) + size_t(j + 1)];
      vcg::tri::Allocator<test_mesh::TMesh>::AddFace(m, a, e, b);
      vcg::tri::Allocator<test_mesh::TMesh>::AddFace(m, a, d, e);
    }
}

// Regions over a chamfered corner: the floor beyond x = -1.5, the wall above z = 1.5, and between them a strip
// with the chamfer's plane as its primitive.
GrowingRegions corner_regions(const GrowingFaces& g, double c)
{
  GrowingRegions r;
  r.primitive = {test_fit::make_plane(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()),
                 test_fit::make_plane(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()),
                 test_fit::make_plane(Eigen::Vector3d(-c, 0, 0), Eigen::Vector3d(-1, 0, 1).normalized())};
  r.faces.resize(3);
  r.label.resize(g.centroid.size());
  for (std::size_t f = 0; f < g.centroid.size(); ++f) {
    const int region = g.centroid[f].x() < -1.5 ? 0 : g.centroid[f].z() > 1.5 ? 1 : 2;
    r.label[f] = region;
    r.faces[std::size_t(region)].push_back(int(f));
  }
  return r;
}

// A strip of a blurred edge: most of its faces lie on the floor or the wall (43% each), a few on a chamfer of
// 0.3 mm. No one neighbour explains half of it, the two do face by face: it dissolves, and its faces go to them.
// A chamfer of 2 mm, a surface of its own, stays.
TEST(DissolveRoughRegions, StripExplainedByItsNeighboursFaceByFaceDissolves)
{
  GrowingScale scale;
  scale.tolerance = 0.1;
  scale.angle = radians_from_degrees(30.0);
  for (const double c : {0.3, 2.0}) {
    test_mesh::TMesh m;
    make_chamfered_corner(m, c, 0.1);
    const FaceAdjacency adj = build_face_adjacency(m);
    const GrowingFaces g = growing_faces(m, adj, 0);
    GrowingRegions regions = corner_regions(g, c);
    RegionPairs adjacent;
    for (const auto& [length, a, b] : merge_detail::region_borders(adj, regions.label))
      adjacent.emplace_back(a, b);
    std::sort(adjacent.begin(), adjacent.end());
    EXPECT_EQ(adjacent, (RegionPairs{{0, 2}, {1, 2}}));
    const std::vector<int> strip = regions.faces[2];
    ASSERT_LT(strip.size(), regions.faces[0].size());
    for (int q : {0, 1})
      EXPECT_LT(sampled_share(g, regions.primitive[std::size_t(q)], strip, 2.0 * scale.tolerance, scale.angle),
                kMergeShare)
          << "one neighbour alone explains the strip (c = " << c << ")";
    const double both = share_near_neighbours(g, regions, strip, {0, 1}, 2.0 * scale.tolerance, scale.angle);
    if (c < 1.0) {
      EXPECT_GT(both, 0.8);
      EXPECT_EQ(dissolve_rough_regions(g, adjacent, scale, regions), 1);
      EXPECT_TRUE(regions.faces[2].empty());
      for (int f : strip)
        EXPECT_EQ(regions.label[std::size_t(f)], -1);
    } else {
      EXPECT_LT(both, 0.2);
      EXPECT_EQ(dissolve_rough_regions(g, adjacent, scale, regions), 0);
      EXPECT_EQ(regions.faces[2], strip);
    }
  }
}


// The floor cut in two at y = 2 (regions 0 and 3, the same plane) merges into region 0; the pairs returned are the
// borders of the merged labels, as a pass over the faces finds them.
TEST(MergeRegions, ReturnsTheBordersOfTheMergedRegions)
{
  GrowingScale scale;
  scale.tolerance = 0.1;
  scale.angle = radians_from_degrees(30.0);
  test_mesh::TMesh m;
  make_chamfered_corner(m, 2.0, 0.1);
  const FaceAdjacency adj = build_face_adjacency(m);
  const GrowingFaces g = growing_faces(m, adj, 0);
  GrowingRegions regions = corner_regions(g, 2.0);
  regions.primitive.push_back(regions.primitive[0]);
  regions.faces.assign(4, {});
  for (std::size_t f = 0; f < g.centroid.size(); ++f) {
    int& label = regions.label[f];
    if (label == 0 && g.centroid[f].y() > 2.0)
      label = 3;
    regions.faces[std::size_t(label)].push_back(int(f));
  }
  const RegionPairs adjacent = merge_regions(g, adj, scale, regions, 1);
  EXPECT_TRUE(regions.faces[3].empty());
  RegionPairs scanned;
  for (const auto& [length, a, b] : merge_detail::region_borders(adj, regions.label))
    scanned.emplace_back(a, b);
  std::sort(scanned.begin(), scanned.end());
  EXPECT_EQ(adjacent, scanned);
  EXPECT_EQ(adjacent, (RegionPairs{{0, 2}, {1, 2}}));
}

} // namespace

namespace {

// GrowingFaces of an extruded profile z = height(x) over a grid of squares of side h (two triangles each),
// x in [x0, x1], y in [0, 2]: exact face normals and areas, every face valid.
template <class Height>
GrowingFaces extruded_profile(double x0, double x1, double h, Height height, FaceAdjacency& adj)
{
  const int nx = int(std::lround((x1 - x0) / h)), ny = int(std::lround(2.0 / h));
  std::vector<Eigen::Vector3d> points;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      points.emplace_back(x0 + i * h, j * h, height(x0 + i * h));
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  std::vector<int> corners;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      for (const int v : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1)})
        corners.push_back(v);
  adj = face_adjacency_from_corners(corners, points.size(), 1);
  GrowingFaces g;
  for (std::size_t f = 0; 3 * f < corners.size(); ++f) {
    const Eigen::Vector3d& a = points[std::size_t(corners[3 * f])];
    const Eigen::Vector3d& b = points[std::size_t(corners[3 * f + 1])];
    const Eigen::Vector3d& c = points[std::size_t(corners[3 * f + 2])];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    g.centroid.push_back((a + b + c) / 3);
    g.normal.push_back(n.normalized());
    g.area.push_back(0.5 * n.norm());
    g.valid.push_back(1);
    g.deleted.push_back(0);
  }
  return g;
}

// wider_type for the region of the faces whose centroid lies at 0 < x < w, grown with `prim` and stopped there;
// `band` is what the candidate type was fitted on.
std::optional<Primitive> wider_type_of_strip(const GrowingFaces& g, const FaceAdjacency& adj, double w,
                                             const GrowingScale& scale, const Primitive& prim,
                                             std::vector<int>& region, std::vector<int>& band)
{
  std::vector<int> label(g.area.size(), -1), open_faces;
  region.clear();
  for (std::size_t f = 0; f < label.size(); ++f)
    if (g.centroid[f].x() > 0 && g.centroid[f].x() < w) {
      label[f] = 0;
      region.push_back(int(f));
    }
  for (int f : region)
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k)
      if (label[std::size_t(adj.neighbour[std::size_t(k)])] < 0) {
        open_faces.push_back(f);
        break;
      }
  FaceStamps stamps;
  stamps.stamp.assign(g.area.size(), 0);
  return grow_detail::wider_type(g, adj, scale, prim, region, open_faces, label, stamps, band, 1);
}

} // namespace

// A flat strip 0.2 wide whose edges turn up as arcs of radius 0.2: the plane it grew with stops at the arcs, and
// the type fitted to it and its rings is a cylinder (radius about 1.1) that bends to the arcs. It fits the strip
// worse than its plane, which fits it exactly: the region stays a plane.
TEST(WiderType, RefusesATypeThatFitsTheStoppedRegionWorse)
{
  FaceAdjacency adj;
  const double w = 0.2, r = 0.2;
  const GrowingFaces g = extruded_profile(-0.6, 0.8, 0.05, [&](double x) {
    const double d = x < 0 ? -x : x > w ? x - w : 0;
    return d >= r ? d : r - std::sqrt(r * r - d * d);
  }, adj);
  GrowingScale scale;
  scale.tolerance = 0.02;
  scale.angle = radians_from_degrees(15);
  const Primitive plane = test_fit::make_plane(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  std::vector<int> region, band;
  EXPECT_FALSE(wider_type_of_strip(g, adj, w, scale, plane, region, band));
  const std::optional<Primitive> fit = fit_region_primitive(g, band, nullptr, scale.tolerance, scale.angle, 0.95);
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->type, PrimitiveType::Cylinder) << "the band's fit, refused";
  EXPECT_GT(sampled_rms(g, *fit, region), 1e-4);
  EXPECT_EQ(sampled_rms(g, plane, region), 0.0);
}

// A strip 0.3 wide of a cylinder of radius 1, grown as the plane fitted to it: the cylinder fitted to it and its
// rings fits the strip better, and takes over.
TEST(WiderType, TakesTheCylinderAStripOfItWasGrownAsAPlane)
{
  FaceAdjacency adj;
  const double w = 0.3, r = 1.0;
  const GrowingFaces g = extruded_profile(-0.6, 0.9, 0.05, [&](double x) {
    return r - std::sqrt(r * r - (x - 0.5 * w) * (x - 0.5 * w));
  }, adj);
  GrowingScale scale;
  scale.tolerance = 0.01;
  scale.angle = radians_from_degrees(15);
  std::vector<int> region, band;
  for (std::size_t f = 0; f < g.area.size(); ++f)
    if (g.centroid[f].x() > 0 && g.centroid[f].x() < w)
      region.push_back(int(f));
  const std::optional<Primitive> plane =
      fit_region_primitive(g, region, nullptr, scale.tolerance, scale.angle, 0.9);
  ASSERT_TRUE(plane);
  ASSERT_EQ(plane->type, PrimitiveType::Plane);
  const std::optional<Primitive> wider = wider_type_of_strip(g, adj, w, scale, *plane, region, band);
  ASSERT_TRUE(wider);
  EXPECT_EQ(wider->type, PrimitiveType::Cylinder);
  EXPECT_NEAR(wider->radius, r, 0.05);
  EXPECT_LT(sampled_rms(g, *wider, region), sampled_rms(g, *plane, region));
}
