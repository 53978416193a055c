// Unit tests of the segmentation core: adjacency, smoothed normals, automatic segmentation, manual edits
// (merge, split by plane, split by selection), colouring and the SegmentId attribute, on the tests' mesh type,
// MeshLab's CMeshO and a float mesh with fixed face quality and colour.
#include "test_mesh.h"

#include "common/mesh/color_segments.h"
#include "common/mesh/compact_segment_ids.h"
#include "common/mesh/count_segments.h"
#include "common/mesh/face_adjacency.h"
#include "common/segment/merge_segments.h"
#include "common/segment/move_faces_to_new_segment.h"
#include "common/mesh/segment_attribute.h"
#include "common/segment/segment_by_normal_angle.h"
#include "common/mesh/smooth_face_normals.h"
#include "common/segment/split_segments_by_plane.h"

#include "meshlab_test_mesh.h"
#include <gtest/gtest.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/create/platonic.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace primitive_edit;

namespace {

class QVertex;
class QFace;
struct QUsedTypes : public vcg::UsedTypes<vcg::Use<QVertex>::AsVertexType, vcg::Use<QFace>::AsFaceType> {};
class QVertex : public vcg::Vertex<QUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::BitFlags> {};
class QFace : public vcg::Face<QUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::BitFlags,
                               vcg::face::Qualityf, vcg::face::Color4b> {};
// A float mesh whose face quality and colour are always present (not optional as in CMeshO).
class QMesh : public vcg::tri::TriMesh<std::vector<QVertex>, std::vector<QFace>> {};

template <class M> void enable_face_quality_and_color(M&) {}
void enable_face_quality_and_color(test_mesh::MeshLabMesh& m)
{
  m.face.EnableQuality();
  m.face.EnableColor();
}

template <class M>
typename M::CoordType coord(double x, double y, double z)
{
  using S = typename M::ScalarType;
  return typename M::CoordType(S(x), S(y), S(z));
}

// Axis-aligned cube [-1,1]^3, each side an n x n grid of quads split in two triangles, outward facing.
template <class M>
void make_grid_cube(M& m, int n)
{
  m.Clear();
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = -1; sign <= 1; sign += 2) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int base = int(m.vert.size());
      auto vi = vcg::tri::Allocator<M>::AddVertices(m, size_t((n + 1) * (n + 1)));
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j, ++vi) {
          double p[3];
          p[axis] = sign;
          p[u] = -1.0 + 2.0 * i / n;
          p[v] = -1.0 + 2.0 * j / n;
          vi->P() = coord<M>(p[0], p[1], p[2]);
        }
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto* a = &m.vert[size_t(base + i * (n + 1) + j)];
          auto* b = &m.vert[size_t(base + (i + 1) * (n + 1) + j)];
          auto* c = &m.vert[size_t(base + (i + 1) * (n + 1) + j + 1)];
          auto* d = &m.vert[size_t(base + i * (n + 1) + j + 1)];
          if (sign > 0) {
            vcg::tri::Allocator<M>::AddFace(m, a, b, c);
            vcg::tri::Allocator<M>::AddFace(m, a, c, d);
          } else {
            vcg::tri::Allocator<M>::AddFace(m, a, c, b);
            vcg::tri::Allocator<M>::AddFace(m, a, d, c);
          }
        }
    }
  vcg::tri::Clean<M>::RemoveDuplicateVertex(m);
  vcg::tri::Allocator<M>::CompactEveryVector(m);
}

// make_grid_cube with each vertex moved by Gaussian noise of std sigma in each coordinate.
template <class M>
void make_noisy_grid_cube(M& m, int n, double sigma, unsigned seed)
{
  make_grid_cube(m, n);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  for (auto& v : m.vert)
    v.P() += coord<M>(noise(rng), noise(rng), noise(rng));
}

// The checks every operation must pass: one entry per face, -1 exactly on deleted faces, ids dense 0..K-1.
template <class M>
void expect_valid_segmentation(const M& m, const std::vector<int>& seg, int K)
{
  ASSERT_EQ(seg.size(), m.face.size());
  int next = 0;
  std::vector<int> seen(size_t(std::max(K, 0)), 0);
  for (size_t f = 0; f < seg.size(); ++f) {
    if (m.face[f].IsD()) {
      EXPECT_EQ(seg[f], -1) << "deleted face " << f;
      continue;
    }
    ASSERT_GE(seg[f], 0) << "live face " << f << " has no segment";
    ASSERT_LT(seg[f], K);
    if (!seen[size_t(seg[f])]) {
      seen[size_t(seg[f])] = 1;
      ++next;
    }
  }
  EXPECT_EQ(next, K) << "some id below K is unused";
}

template <class M>
Eigen::Vector3d face_centroid(const M& m, size_t f)
{
  const auto c = (m.face[f].cP(0) + m.face[f].cP(1) + m.face[f].cP(2)) / 3;
  return {double(c[0]), double(c[1]), double(c[2])};
}

// vcg's ~TriMesh does not free per-face attributes (its ClearAttributes call is commented out): tests that
// write the SegmentId attribute release it on exit so that LeakSanitizer stays quiet.
template <class M>
struct AttributeRelease
{
  M& m;
  ~AttributeRelease() { m.ClearAttributes(); }
};

int count_segments(const std::vector<int>& seg)
{
  return seg.empty() ? 0 : *std::max_element(seg.begin(), seg.end()) + 1;
}

template <class M>
class SegmentationTest : public ::testing::Test {};
using SegmentationMeshTypes =
    ::testing::Types<test_mesh::TMesh, test_mesh::MeshLabMesh, test_mesh::FreesAttributes<QMesh>>;
TYPED_TEST_SUITE(SegmentationTest, SegmentationMeshTypes);

TYPED_TEST(SegmentationTest, AdjacencyOfClosedManifoldHasThreeSymmetricNeighbours)
{
  TypeParam m;
  vcg::tri::Sphere(m, 3);
  const FaceAdjacency adj = build_face_adjacency(m);
  ASSERT_EQ(adj.face_count(), m.fn);
  for (int f = 0; f < adj.face_count(); ++f) {
    ASSERT_EQ(adj.offset[size_t(f) + 1] - adj.offset[size_t(f)], 3) << "face " << f;
    for (int k = adj.offset[size_t(f)]; k < adj.offset[size_t(f) + 1]; ++k) {
      const int g = adj.neighbour[size_t(k)];
      EXPECT_NE(g, f);
      const auto begin = adj.neighbour.begin() + adj.offset[size_t(g)];
      const auto end = adj.neighbour.begin() + adj.offset[size_t(g) + 1];
      EXPECT_NE(std::find(begin, end, f), end) << "adjacency not symmetric";
    }
  }
}

TYPED_TEST(SegmentationTest, NonManifoldEdgeLinksAllItsFaces)
{
  TypeParam m;
  auto vi = vcg::tri::Allocator<TypeParam>::AddVertices(m, 5);
  vi[0].P() = coord<TypeParam>(0, 0, 0);
  vi[1].P() = coord<TypeParam>(1, 0, 0);
  vi[2].P() = coord<TypeParam>(0, 1, 0);
  vi[3].P() = coord<TypeParam>(0, -1, 0);
  vi[4].P() = coord<TypeParam>(0, 0, 1);
  auto* v = &m.vert[0];
  vcg::tri::Allocator<TypeParam>::AddFace(m, v + 0, v + 1, v + 2);
  vcg::tri::Allocator<TypeParam>::AddFace(m, v + 1, v + 0, v + 3);
  vcg::tri::Allocator<TypeParam>::AddFace(m, v + 0, v + 1, v + 4);
  const FaceAdjacency adj = build_face_adjacency(m);
  for (int f = 0; f < 3; ++f) {
    std::vector<int> n(adj.neighbour.begin() + adj.offset[size_t(f)], adj.neighbour.begin() + adj.offset[size_t(f) + 1]);
    std::sort(n.begin(), n.end());
    std::vector<int> expected;
    for (int g = 0; g < 3; ++g)
      if (g != f)
        expected.push_back(g);
    EXPECT_EQ(n, expected) << "face " << f;
  }
  std::vector<int> seg;
  const int K = segment_by_normal_angle(m, SegmentByNormalAngleParams{20.0, 2, 1}, seg);
  expect_valid_segmentation(m, seg, K);
  // Faces 0 and 1 lie in the xy plane with the same normal, face 2 in the xz plane.
  EXPECT_EQ(K, 2);
  EXPECT_EQ(seg[0], seg[1]);
  EXPECT_NE(seg[0], seg[2]);
}

TYPED_TEST(SegmentationTest, HexahedronGivesSixSegments)
{
  TypeParam m;
  vcg::tri::Hexahedron(m);
  std::vector<int> seg;
  const int K = segment_by_normal_angle(m, SegmentByNormalAngleParams{20.0, 2, 1}, seg);
  expect_valid_segmentation(m, seg, K);
  EXPECT_EQ(K, 6);
}

TYPED_TEST(SegmentationTest, TessellatedCubeGivesSixSegmentsWithDefaults)
{
  TypeParam m;
  make_grid_cube(m, 12);
  std::vector<int> seg;
  const int K = segment_by_normal_angle(m, SegmentByNormalAngleParams{}, seg);
  expect_valid_segmentation(m, seg, K);
  ASSERT_EQ(K, 6);
  // Each segment is one side: all its raw face normals agree.
  std::vector<int> size(6, 0);
  for (int s : seg)
    ++size[size_t(s)];
  for (int s : size)
    EXPECT_EQ(s, 2 * 12 * 12);
}

TYPED_TEST(SegmentationTest, CappedCylinderGivesThreeSegmentsAtThirtyDegrees)
{
  TypeParam m;
  vcg::tri::Cylinder(64, 20, m, true);
  ASSERT_EQ(m.fn, 64 * 20 * 2 + 2 * 64) << "vcg's cylinder is expected to have triangulated caps";
  std::vector<int> seg;
  const int K = segment_by_normal_angle(m, SegmentByNormalAngleParams{30.0, 2, 30}, seg);
  expect_valid_segmentation(m, seg, K);
  ASSERT_EQ(K, 3);
  // The side (axis y) is the biggest segment; the caps have 64 faces each.
  std::vector<int> size(3, 0);
  for (int s : seg)
    ++size[size_t(s)];
  std::sort(size.begin(), size.end());
  EXPECT_EQ(size[0], 64);
  EXPECT_EQ(size[1], 64);
  EXPECT_EQ(size[2], 64 * 20 * 2);
}

// A scan-like cube: vertex noise of 0.3 times the edge length tilts each face normal by tens of degrees. The
// paper's 2 crease-gated passes shatter it; the defaults measure the noise, smooth as much as it needs, stop
// the fill at the edge faces and give back the 6 sides.
TYPED_TEST(SegmentationTest, NoisyCubeGivesSixSidesWithDefaults)
{
  const int n = 40;
  TypeParam m;
  make_grid_cube(m, n);
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.3 * 2.0 / n);
  for (auto& v : m.vert)
    v.P() += coord<TypeParam>(noise(rng), noise(rng), noise(rng));
  const FaceAdjacency adj = build_face_adjacency(m);

  std::vector<int> paper;
  EXPECT_GT(segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{20.0, 2, 30}, paper), 6);

  std::vector<int> seg;
  SegmentByNormalAngleReport report;
  const int K = segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{}, seg, {}, &report);
  expect_valid_segmentation(m, seg, K);
  EXPECT_TRUE(report.edge_faces);
  EXPECT_GT(report.smoothing_passes, kPaperSmoothingPasses);
  EXPECT_GT(report.noise, 0.0);
  ASSERT_EQ(K, 6);
  // Faces were built side after side, 2 n^2 each: every side is mostly one segment of its own (edge faces are
  // split near the middle of each ramp, a face or two off the true edge: a few percent of a 40 x 40 side).
  const size_t side_faces = size_t(2 * n * n);
  std::vector<std::vector<int>> count(6, std::vector<int>(6, 0));
  for (size_t f = 0; f < seg.size(); ++f)
    ++count[f / side_faces][size_t(seg[f])];
  std::vector<int> segment_of_side(6);
  for (size_t side = 0; side < 6; ++side) {
    const auto best = std::max_element(count[side].begin(), count[side].end());
    segment_of_side[side] = int(best - count[side].begin());
    EXPECT_GT(*best, int(0.9 * double(side_faces))) << "side " << side;
  }
  std::sort(segment_of_side.begin(), segment_of_side.end());
  EXPECT_EQ(std::unique(segment_of_side.begin(), segment_of_side.end()), segment_of_side.end());

  std::vector<int> again;
  EXPECT_EQ(segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{}, again), K);
  EXPECT_EQ(again, seg) << "not deterministic";
}

TEST(NormalAngleParams, OutOfRangeValuesAreRefusedByName)
{
  EXPECT_TRUE(check_normal_angle_params(SegmentByNormalAngleParams{}).ok());
  EXPECT_TRUE(check_normal_angle_params(SegmentByNormalAngleParams{20.0, 0, 0}).ok());
  EXPECT_TRUE(check_normal_angle_params(SegmentByNormalAngleParams{179.0, 1000, 1000000}).ok());
  const Status angle = check_normal_angle_params(SegmentByNormalAngleParams{0.0, -1, -1});
  EXPECT_FALSE(angle.ok());
  EXPECT_NE(angle.error.find("Angle"), std::string::npos);
  const Status smoothing = check_normal_angle_params(SegmentByNormalAngleParams{20.0, -2, -1});
  EXPECT_FALSE(smoothing.ok());
  EXPECT_NE(smoothing.error.find("Normal Smoothing Steps"), std::string::npos);
  EXPECT_FALSE(check_normal_angle_params(SegmentByNormalAngleParams{20.0, 1001, -1}).ok());
  const Status size = check_normal_angle_params(SegmentByNormalAngleParams{20.0, -1, -2});
  EXPECT_FALSE(size.ok());
  EXPECT_NE(size.error.find("Min Segment Size"), std::string::npos);
  EXPECT_FALSE(check_normal_angle_params(SegmentByNormalAngleParams{std::nan(""), -1, -1}).ok());
}

TYPED_TEST(SegmentationTest, SphereGivesOneSegment)
{
  TypeParam m;
  vcg::tri::Sphere(m, 4);
  std::vector<int> seg;
  const int K = segment_by_normal_angle(m, SegmentByNormalAngleParams{}, seg);
  expect_valid_segmentation(m, seg, K);
  EXPECT_EQ(K, 1);
}

TYPED_TEST(SegmentationTest, SmallerAngleGivesAtLeastAsManySegments)
{
  TypeParam torus, cylinder, noisy;
  vcg::tri::Torus(torus, 3.0f, 1.0f, 48, 24);
  vcg::tri::Cylinder(32, 8, cylinder, true);
  vcg::tri::Sphere(noisy, 4);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (auto& v : noisy.vert)
    v.P() += coord<TypeParam>(noise(rng), noise(rng), noise(rng));
  for (TypeParam* m : {&torus, &cylinder, &noisy}) {
    int previous = std::numeric_limits<int>::max();
    int first = 0;
    for (double angle : {2.0, 5.0, 10.0, 20.0, 40.0, 80.0}) {
      std::vector<int> seg;
      const int K = segment_by_normal_angle(*m, SegmentByNormalAngleParams{angle, 2, 5}, seg);
      expect_valid_segmentation(*m, seg, K);
      EXPECT_LE(K, previous) << "angle " << angle;
      previous = K;
      if (angle == 2.0)
        first = K;
    }
    EXPECT_GT(first, previous) << "the angle has no effect";
  }
}

TYPED_TEST(SegmentationTest, SmoothingGivesUnitNormalsAndReducesNoise)
{
  TypeParam m;
  make_noisy_grid_cube(m, 30, 0.004, 3);
  const FaceAdjacency adj = build_face_adjacency(m);
  // Mean angle between each face normal and its side's exact normal (the dominant axis of its centroid).
  auto mean_error = [&](const std::vector<Eigen::Vector3d>& normal) {
    double sum = 0.0;
    for (size_t f = 0; f < m.face.size(); ++f) {
      EXPECT_NEAR(normal[f].norm(), 1.0, 1e-9);
      const auto c = (m.face[f].cP(0) + m.face[f].cP(1) + m.face[f].cP(2)) / 3;
      const Eigen::Vector3d centroid{double(c[0]), double(c[1]), double(c[2])};
      Eigen::Index axis;
      centroid.cwiseAbs().maxCoeff(&axis);
      Eigen::Vector3d exact = Eigen::Vector3d::Zero();
      exact[axis] = centroid[axis] > 0 ? 1.0 : -1.0;
      sum += std::acos(std::clamp(normal[f].dot(exact), -1.0, 1.0));
    }
    return sum / double(m.face.size());
  };
  const double raw = mean_error(smooth_face_normals(m, adj, 0));
  const double smoothed = mean_error(smooth_face_normals(m, adj, 3, 40.0));
  EXPECT_GT(raw, 0.05);
  EXPECT_LT(smoothed, 0.6 * raw);
}

TYPED_TEST(SegmentationTest, UngatedSmoothingIsThePlainAreaWeightedAverage)
{
  // The ungated passes keep area-weighted normals between passes; the normals must be the bits of the plain
  // average of each face's and its neighbours' area-weighted normals, pass after pass, threads or not.
  TypeParam m;
  make_noisy_grid_cube(m, 20, 0.01, 5);
  const FaceAdjacency adj = build_face_adjacency(m);
  std::vector<Eigen::Vector3d> expected;
  const std::vector<double> area = face_centroids_and_areas(m, 1, &expected).area;
  for (int pass = 0; pass < 4; ++pass) {
    std::vector<Eigen::Vector3d> next(expected.size());
    for (std::size_t f = 0; f < expected.size(); ++f) {
      Eigen::Vector3d sum = area[f] * expected[f];
      for (int i = adj.offset[f]; i < adj.offset[f + 1]; ++i)
        sum += area[std::size_t(adj.neighbour[std::size_t(i)])] * expected[std::size_t(adj.neighbour[std::size_t(i)])];
      next[f] = sum / sum.norm();
    }
    expected.swap(next);
  }
  for (int threads : {1, 2}) {
    const std::vector<Eigen::Vector3d> got = smooth_face_normals(m, adj, 4, 180.0, threads);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t f = 0; f < got.size(); ++f)
      ASSERT_EQ(got[f], expected[f]) << "face " << f << ", " << threads << " thread(s)";
  }
}

TYPED_TEST(SegmentationTest, MergeJoinsListedSegmentsOnly)
{
  TypeParam m;
  make_grid_cube(m, 6);
  std::vector<int> seg;
  ASSERT_EQ(segment_by_normal_angle(m, SegmentByNormalAngleParams{}, seg), 6);
  const std::vector<int> before = seg;

  EXPECT_EQ(merge_segments(seg, {1, 4}), 5);
  expect_valid_segmentation(m, seg, 5);
  for (size_t f = 0; f < seg.size(); ++f)
    for (size_t g = 0; g < seg.size(); g += 7) {
      const bool merged_f = before[f] == 1 || before[f] == 4, merged_g = before[g] == 1 || before[g] == 4;
      const bool together_before = before[f] == before[g] || (merged_f && merged_g);
      ASSERT_EQ(seg[f] == seg[g], together_before) << f << " " << g;
    }

  EXPECT_EQ(merge_segments(seg, {42, -3}), 5) << "unknown ids change nothing";
  expect_valid_segmentation(m, seg, 5);
  EXPECT_EQ(merge_segments(seg, {0, 1, 2, 3, 4, 4}), 1);
  expect_valid_segmentation(m, seg, 1);
}

TYPED_TEST(SegmentationTest, SplitByPlaneSeparatesSidesAndConnectedPieces)
{
  TypeParam m;
  make_grid_cube(m, 8);
  const FaceAdjacency adj = build_face_adjacency(m);
  std::vector<int> seg;
  ASSERT_EQ(segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{}, seg), 6);
  // The segment of the face whose centroid is nearest to p.
  auto segment_at = [&](const Eigen::Vector3d& p) {
    size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (size_t f = 0; f < m.face.size(); ++f) {
      const double distance = (face_centroid(m, f) - p).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best = f;
      }
    }
    return seg[best];
  };

  // Top side cut by the plane x = 0: two halves.
  const int top = segment_at(Eigen::Vector3d::UnitZ());
  int K = split_segments_by_plane(m, adj, seg, {top}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX());
  expect_valid_segmentation(m, seg, K);
  EXPECT_EQ(K, 7);

  // Top and bottom halves at x > 0 merged into one disconnected segment, then cut by y = 0 (normal not
  // unit): four connected pieces.
  const int top_right = segment_at(Eigen::Vector3d(0.5, 0.1, 1));
  const int bottom = segment_at(-Eigen::Vector3d::UnitZ());
  K = merge_segments(seg, {top_right, bottom});
  expect_valid_segmentation(m, seg, K);
  EXPECT_EQ(K, 6);
  const int merged = segment_at(-Eigen::Vector3d::UnitZ());
  EXPECT_EQ(segment_at(Eigen::Vector3d(0.5, 0.1, 1)), merged);
  K = split_segments_by_plane(m, adj, seg, {merged}, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 3, 0));
  expect_valid_segmentation(m, seg, K);
  EXPECT_EQ(K, 9);
  for (size_t f = 0; f < m.face.size(); ++f) {
    const auto c = (m.face[f].cP(0) + m.face[f].cP(1) + m.face[f].cP(2)) / 3;
    // The four pieces of the merged segment: (top x>0, bottom) x (y<0, y>0), each its own id.
    if (std::abs(double(c[2]) - 1.0) < 1e-6 && double(c[0]) > 0)
      for (size_t g = 0; g < m.face.size(); ++g) {
        const auto d = (m.face[g].cP(0) + m.face[g].cP(1) + m.face[g].cP(2)) / 3;
        if (std::abs(double(d[2]) + 1.0) < 1e-6) {
          ASSERT_NE(seg[f], seg[g]);
        }
      }
  }

  // A degenerate plane leaves everything as is.
  const std::vector<int> before = seg;
  K = split_segments_by_plane(m, adj, seg, {0, 1}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  EXPECT_EQ(K, 9);
  EXPECT_EQ(seg, before);
}

// A segment with a face apart from its body (as the scan segmentation leaves them) cut with a smallest piece: the
// stray face stays in the segment's largest piece instead of becoming a segment of one face.
TYPED_TEST(SegmentationTest, SplitByPlaneKeepsStrayFacesInTheirSegment)
{
  TypeParam m;
  make_grid_cube(m, 8);
  const FaceAdjacency adj = build_face_adjacency(m);
  std::vector<int> seg;
  ASSERT_EQ(segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{}, seg), 6);
  size_t top_face = 0, stray = 0;
  for (size_t f = 0; f < m.face.size(); ++f) {
    top_face = face_centroid(m, f).z() > 0.99 ? f : top_face;
    stray = face_centroid(m, f).z() < -0.99 ? f : stray;
  }
  const int top = seg[top_face];
  seg[stray] = top;  // one face of the bottom in the top's segment
  SplitOptions options;
  options.min_piece_faces = kMinSplitPieceFaces;
  const int K =
      split_segments_by_plane(m, adj, seg, {top}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), options);
  expect_valid_segmentation(m, seg, K);
  EXPECT_EQ(K, 7) << "the top's two halves and the other five sides";
  std::vector<int> size(std::size_t(K), 0);
  for (int s : seg)
    ++size[std::size_t(s)];
  for (int n : size)
    EXPECT_GE(n, kMinSplitPieceFaces);
  const int half = seg[stray];
  int top_faces_with_it = 0;
  for (size_t f = 0; f < m.face.size(); ++f)
    top_faces_with_it += seg[f] == half && face_centroid(m, f).z() > 0.99 ? 1 : 0;
  EXPECT_EQ(top_faces_with_it, 64) << "it went with one half of the top";
}

TYPED_TEST(SegmentationTest, MoveFacesToNewSegment)
{
  TypeParam m;
  vcg::tri::Sphere(m, 3);
  std::vector<int> seg;
  ASSERT_EQ(segment_by_normal_angle(m, SegmentByNormalAngleParams{}, seg), 1);
  std::vector<int> selected;
  for (size_t f = 0; f < m.face.size(); ++f)
    if (m.face[f].cP(0)[2] > 0.5f && m.face[f].cP(1)[2] > 0.5f && m.face[f].cP(2)[2] > 0.5f)
      selected.push_back(int(f));
  ASSERT_FALSE(selected.empty());
  selected.push_back(-5);
  selected.push_back(int(m.face.size()) + 3);
  selected.push_back(selected.front());
  const int K = move_faces_to_new_segment(seg, selected);
  expect_valid_segmentation(m, seg, K);
  EXPECT_EQ(K, 2);
  const int moved = seg[size_t(selected.front())];
  for (size_t f = 0; f < m.face.size(); ++f) {
    const bool is_selected = std::find(selected.begin(), selected.end(), int(f)) != selected.end();
    EXPECT_EQ(seg[f] == moved, is_selected) << "face " << f;
  }
}

TYPED_TEST(SegmentationTest, CompactIdsKeepsPartitionAndOrder)
{
  std::vector<int> seg = {7, 7, -4, 2000000000, 3, 7, -1, 3, 2000000000};
  EXPECT_EQ(compact_segment_ids(seg), 3);
  EXPECT_EQ(seg, (std::vector<int>{1, 1, -1, 2, 0, 1, -1, 0, 2}));
  std::vector<int> sparse = {5, 1, 5, 0};
  EXPECT_EQ(compact_segment_ids(sparse), 3);
  EXPECT_EQ(sparse, (std::vector<int>{2, 1, 2, 0}));
  // Dense ids in any order are kept as they are: they are the ids the user reads in the face quality.
  std::vector<int> dense = {2, 0, 1, 2, -1, 0};
  EXPECT_EQ(compact_segment_ids(dense), 3);
  EXPECT_EQ(dense, (std::vector<int>{2, 0, 1, 2, -1, 0}));
  std::vector<int> none = {-1, -1};
  EXPECT_EQ(compact_segment_ids(none), 0);
}

TYPED_TEST(SegmentationTest, DegenerateNanAndDeletedFacesDoNotBreakAnything)
{
  TypeParam m;
  const AttributeRelease<TypeParam> release{m};
  make_grid_cube(m, 6);
  const int live_before = m.fn;
  auto* v = &m.vert[0];
  // Repeated vertex, zero area (collinear), a NaN vertex, and a deleted face.
  // vcg's AddFace asserts on a repeated vertex, so that face is filled in by hand.
  auto degenerate = vcg::tri::Allocator<TypeParam>::AddFaces(m, 1);
  degenerate->V(0) = v + 0;
  degenerate->V(1) = v + 0;
  degenerate->V(2) = v + 1;
  auto vi = vcg::tri::Allocator<TypeParam>::AddVertices(m, 2);
  v = &m.vert[0];
  vi[0].P() = (v[0].P() + v[1].P()) / 2;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vi[1].P() = coord<TypeParam>(nan, 0.0, nan);
  vcg::tri::Allocator<TypeParam>::AddFace(m, v + 0, v + 1, &*vi);
  vcg::tri::Allocator<TypeParam>::AddFace(m, v + 2, v + 3, &*(vi + 1));
  vcg::tri::Allocator<TypeParam>::DeleteFace(m, m.face[5]);
  ASSERT_EQ(m.fn, live_before + 2);
  enable_face_quality_and_color(m);

  const FaceAdjacency adj = build_face_adjacency(m);
  for (const Eigen::Vector3d& n : smooth_face_normals(m, adj, 3))
    EXPECT_TRUE(n.allFinite());
  EXPECT_TRUE(smooth_face_normals(m, adj, 0)[5].isZero(0.0)) << "deleted face";

  for (int min_faces : {1, 30}) {
    std::vector<int> seg;
    const int K = segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{20.0, 2, min_faces}, seg);
    expect_valid_segmentation(m, seg, K);
    EXPECT_GE(K, 6);
    int k = split_segments_by_plane(m, adj, seg, {0, 1, 2}, Eigen::Vector3d(0.1, 0.2, 0.3),
                                    Eigen::Vector3d(1, 1, 0));
    expect_valid_segmentation(m, seg, k);
    k = move_faces_to_new_segment(seg, {5, 0, int(m.face.size()) - 1});
    expect_valid_segmentation(m, seg, k);
    EXPECT_EQ(seg[5], -1) << "a deleted face joins no segment";
    const std::vector<vcg::Color4b> colour = color_segments(m, adj, seg);
    EXPECT_EQ(int(colour.size()), k);
    write_segment_ids(m, seg);
    std::vector<int> back;
    ASSERT_TRUE(read_segment_ids(m, back));
    EXPECT_EQ(back, seg);
  }

  // Bad parameters and an adjacency of another mesh.
  std::vector<int> seg;
  EXPECT_GE(segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{nan, -3, -1}, seg), 1);
  expect_valid_segmentation(m, seg, count_segments(seg));
  EXPECT_EQ(segment_by_normal_angle(m, FaceAdjacency{}, SegmentByNormalAngleParams{}, seg), 0);
  TypeParam empty;
  EXPECT_EQ(segment_by_normal_angle(empty, SegmentByNormalAngleParams{}, seg), 0);
  EXPECT_TRUE(seg.empty());
}

TYPED_TEST(SegmentationTest, SmallSegmentIsAbsorbedByNeighbourWithLongestBorder)
{
  const int n = 10;
  TypeParam m;
  make_grid_cube(m, n);
  const FaceAdjacency adj = build_face_adjacency(m);
  std::vector<int> seg;
  ASSERT_EQ(segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{}, seg), 6);
  // A strip of 3 cells of the top side (z = 1, the last side built) along its x = 1 edge, from the y = -1
  // corner, made its own segment. It borders the rest of the top along 4 cell edges, the x = 1 side along 3
  // and the y = -1 side along 1; the x = 1 side is the bigger segment, but the top's border is longer.
  const size_t top_first_face = 5 * size_t(2 * n * n);
  const int top = seg[top_first_face];
  std::vector<int> strip;
  for (int j = 0; j < 3; ++j)
    for (int t = 0; t < 2; ++t)
      strip.push_back(int(top_first_face) + 2 * ((n - 1) * n + j) + t);
  for (int f : strip)
    seg[size_t(f)] = 6;
  const std::vector<int> before = seg;
  detail::absorb_small_segments(m, adj, 30, seg, 7);
  for (size_t f = 0; f < seg.size(); ++f)
    EXPECT_EQ(seg[f], before[f] == 6 ? top : before[f]) << "face " << f;
}

TYPED_TEST(SegmentationTest, BumpIsAbsorbedIntoItsOnlyNeighbour)
{
  TypeParam m;
  make_grid_cube(m, 10);
  std::vector<int> seg;
  const FaceAdjacency adj = build_face_adjacency(m);
  ASSERT_EQ(segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{}, seg), 6);
  // Lift one interior vertex of the top side: its 6 faces tilt steeply and form their own segment
  // without absorption, and are absorbed into the top side (their only neighbour) with absorption.
  size_t top_center = 0;
  for (size_t v = 0; v < m.vert.size(); ++v)
    if ((m.vert[v].cP() - coord<TypeParam>(0, 0, 1)).Norm() < 1e-6)
      top_center = v;
  m.vert[top_center].P() = coord<TypeParam>(0, 0, 1.3);
  EXPECT_GT(segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{10.0, 0, 1}, seg), 6);
  EXPECT_EQ(segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{10.0, 0, 30}, seg), 6);
  expect_valid_segmentation(m, seg, 6);
}

TYPED_TEST(SegmentationTest, ProgressCallbackReachesHundred)
{
  TypeParam m;
  vcg::tri::Sphere(m, 3);
  static std::vector<int> calls;
  calls.clear();
  std::vector<int> seg;
  segment_by_normal_angle(m, SegmentByNormalAngleParams{}, seg, [](const int pos, const char*) {
    calls.push_back(pos);
    return true;
  });
  ASSERT_FALSE(calls.empty());
  EXPECT_EQ(calls.back(), 100);
  EXPECT_TRUE(std::is_sorted(calls.begin(), calls.end()));
  EXPECT_GE(calls.front(), 0);
}

TYPED_TEST(SegmentationTest, AdjacentSegmentsGetDifferentColours)
{
  TypeParam m;
  vcg::tri::Torus(m, 3.0f, 1.0f, 48, 24);
  const FaceAdjacency adj = build_face_adjacency(m);
  std::vector<int> coarse;
  segment_by_normal_angle(m, adj, SegmentByNormalAngleParams{10.0, 0, 1}, coarse);
  // Every face its own segment: thousands of segments, far more than the palette.
  std::vector<int> fine(m.face.size());
  for (size_t f = 0; f < fine.size(); ++f)
    fine[f] = int(f);
  for (const std::vector<int>* seg : {&coarse, &fine}) {
    const std::vector<vcg::Color4b> colour = color_segments(m, adj, *seg);
    ASSERT_EQ(int(colour.size()), count_segments(*seg));
    for (int f = 0; f < adj.face_count(); ++f)
      for (int k = adj.offset[size_t(f)]; k < adj.offset[size_t(f) + 1]; ++k) {
        const int a = (*seg)[size_t(f)], b = (*seg)[size_t(adj.neighbour[size_t(k)])];
        if (a != b) {
          ASSERT_NE(colour[size_t(a)], colour[size_t(b)]) << "segments " << a << " and " << b;
        }
      }
  }
}

TYPED_TEST(SegmentationTest, WriteReadRoundTripThroughAttribute)
{
  TypeParam m;
  const AttributeRelease<TypeParam> release{m};
  vcg::tri::Cylinder(64, 20, m, true);
  enable_face_quality_and_color(m);
  vcg::tri::Allocator<TypeParam>::DeleteFace(m, m.face[10]);
  std::vector<int> seg;
  const int K = segment_by_normal_angle(m, SegmentByNormalAngleParams{30.0, 2, 30}, seg);
  ASSERT_EQ(K, 3);
  std::vector<int> back;
  // Before writing there is no attribute; a mesh with face quality (all zero) reads as one segment.
  EXPECT_EQ(read_segment_ids(m, back), vcg::tri::HasPerFaceQuality(m));
  write_segment_ids(m, seg);
  ASSERT_TRUE(read_segment_ids(m, back));
  EXPECT_EQ(back, seg);
  if (vcg::tri::HasPerFaceColor(m)) {
    // One colour per segment, and a different one across every border.
    const FaceAdjacency adj = build_face_adjacency(m);
    std::vector<vcg::Color4b> colour_of_segment(static_cast<size_t>(K));
    for (size_t f = 0; f < m.face.size(); ++f)
      if (!m.face[f].IsD())
        colour_of_segment[size_t(seg[f])] = m.face[f].C();
    for (int f = 0; f < adj.face_count(); ++f) {
      if (m.face[size_t(f)].IsD())
        continue;
      ASSERT_EQ(m.face[size_t(f)].C(), colour_of_segment[size_t(seg[size_t(f)])]);
      for (int k = adj.offset[size_t(f)]; k < adj.offset[size_t(f) + 1]; ++k) {
        const size_t g = size_t(adj.neighbour[size_t(k)]);
        if (seg[g] != seg[size_t(f)]) {
          ASSERT_NE(m.face[size_t(f)].C(), m.face[g].C());
        }
      }
    }
    // The caller's adjacency, when given, colours exactly as the one built inside.
    std::vector<vcg::Color4b> built(m.face.size());
    for (size_t f = 0; f < m.face.size(); ++f)
      built[f] = m.face[f].C();
    write_segment_ids(m, seg, &adj);
    for (size_t f = 0; f < m.face.size(); ++f)
      ASSERT_EQ(m.face[f].C(), built[f]);
  }

  // An attribute of the right name but the wrong type is replaced, not misread.
  vcg::tri::Allocator<TypeParam>::DeletePerFaceAttribute(m, kSegmentAttributeName);
  auto wrong = vcg::tri::Allocator<TypeParam>::template AddPerFaceAttribute<float>(m, kSegmentAttributeName);
  for (size_t f = 0; f < m.face.size(); ++f)
    wrong[f] = 0.5f;
  std::vector<int> other(seg);
  merge_segments(other, {0, 1});
  write_segment_ids(m, other);
  ASSERT_TRUE(read_segment_ids(m, back));
  EXPECT_EQ(back, other);
}

TYPED_TEST(SegmentationTest, WriteReadRoundTripThroughFaceQualityOnly)
{
  TypeParam m;
  const AttributeRelease<TypeParam> release{m};
  make_grid_cube(m, 5);
  enable_face_quality_and_color(m);
  std::vector<int> seg;
  ASSERT_EQ(segment_by_normal_angle(m, SegmentByNormalAngleParams{}, seg), 6);
  write_segment_ids(m, seg);
  // A PLY reopened: the attribute is gone, only the face quality is left.
  ASSERT_TRUE(vcg::tri::Allocator<TypeParam>::DeletePerFaceAttribute(m, kSegmentAttributeName));
  std::vector<int> back;
  if (!vcg::tri::HasPerFaceQuality(m)) {
    EXPECT_FALSE(read_segment_ids(m, back));
    EXPECT_EQ(std::count(back.begin(), back.end(), -1), long(m.face.size()));
    return;
  }
  ASSERT_TRUE(read_segment_ids(m, back));
  EXPECT_EQ(back, seg);
  // Quality that is not an id (fractional or negative) is no segmentation.
  m.face[3].Q() = 2.5f;
  EXPECT_FALSE(read_segment_ids(m, back));
  m.face[3].Q() = -1.0f;
  EXPECT_FALSE(read_segment_ids(m, back));
  // Dense ids in an order no segmentation would give (a labelled scan from another tool) are kept.
  m.face[3].Q() = float(seg[3]);
  const int K = count_segments(seg);
  std::vector<int> reversed(seg);
  for (size_t f = 0; f < m.face.size(); ++f) {
    reversed[f] = K - 1 - seg[f];
    m.face[f].Q() = float(reversed[f]);
  }
  bool renumbered = true;
  ASSERT_TRUE(read_segment_ids(m, back, &renumbered));
  EXPECT_EQ(back, reversed);
  EXPECT_FALSE(renumbered);
  // Ids stored sparse (as another tool might) are compacted on reading, keeping their order.
  for (auto& f : m.face)
    f.Q() = f.Q() * 10 + 3;
  ASSERT_TRUE(read_segment_ids(m, back, &renumbered));
  EXPECT_EQ(back, reversed);
  EXPECT_TRUE(renumbered);
}

} // namespace
