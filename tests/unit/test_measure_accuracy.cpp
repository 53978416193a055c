// Tests of common/mesh/sample_surface_uniform.h and common/measure/measure_accuracy.h, on the test mesh type and on
// MeshLab's CMeshO.
#include "common/base/constants.h"
#include "common/measure/measure_accuracy.h"
#include "common/mesh/sample_surface_uniform.h"

#include "test_mesh.h"

#include "meshlab_test_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using primitive_edit::AccuracyReport;
using primitive_edit::SurfaceDistanceIndex;
using primitive_edit::Status;


template <class M>
void add_grid_faces(M& m, int rows, int cols)
{
  // Vertex (i, j) of a (rows + 1) x (cols + 1) lattice is vertex i * (cols + 1) + j.
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const int v00 = i * (cols + 1) + j, v01 = v00 + 1, v10 = v00 + cols + 1, v11 = v10 + 1;
      vcg::tri::Allocator<M>::AddFace(m, &m.vert[v00], &m.vert[v01], &m.vert[v11]);
      vcg::tri::Allocator<M>::AddFace(m, &m.vert[v00], &m.vert[v11], &m.vert[v10]);
    }
}

// A size x size square at height z, centred on the z axis, of 2 n^2 triangles.
template <class M>
void make_plate(M& m, int n, double size, double z)
{
  m.Clear();
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      vcg::tri::Allocator<M>::AddVertex(
          m, typename M::CoordType(size * (double(j) / n - 0.5), size * (double(i) / n - 0.5), z));
  add_grid_faces(m, n, n);
}

// A latitude-longitude sphere (poles as rings of coincident vertices, so the pole triangles are degenerate).
template <class M>
void make_uv_sphere(M& m, double radius, int stacks, int slices)
{
  m.Clear();
  for (int i = 0; i <= stacks; ++i) {
    const double theta = primitive_edit::kPi * double(i) / stacks;
    const double ring = (i == 0 || i == stacks) ? 0.0 : radius * std::sin(theta);  // exact poles
    for (int j = 0; j <= slices; ++j) {
      const double phi = 2.0 * primitive_edit::kPi * double(j) / slices;
      vcg::tri::Allocator<M>::AddVertex(
          m, typename M::CoordType(ring * std::cos(phi), ring * std::sin(phi), radius * std::cos(theta)));
    }
  }
  add_grid_faces(m, stacks, slices);
}

template <class M>
void make_triangles(M& m, const std::vector<Eigen::Vector3d>& corners)
{
  m.Clear();
  for (const auto& c : corners)
    vcg::tri::Allocator<M>::AddVertex(m, typename M::CoordType(c.x(), c.y(), c.z()));
  for (size_t k = 0; k + 2 < corners.size(); k += 3)
    vcg::tri::Allocator<M>::AddFace(m, &m.vert[k], &m.vert[k + 1], &m.vert[k + 2]);
}

// Barycentric coordinates of p (assumed in the plane of abc).
Eigen::Vector3d barycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c)
{
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double area2 = n.squaredNorm();
  const double u = (c - b).cross(p - b).dot(n) / area2;
  const double v = (a - c).cross(p - c).dot(n) / area2;
  return Eigen::Vector3d(u, v, 1.0 - u - v);
}

template <class M>
class MeasureAccuracyTest : public ::testing::Test {};

using MeshTypes = ::testing::Types<test_mesh::TMesh, test_mesh::MeshLabMesh>;
TYPED_TEST_SUITE(MeasureAccuracyTest, MeshTypes);

TYPED_TEST(MeasureAccuracyTest, PlateAgainstOffsetPlaneIsAtTheOffsetEverywhere)
{
  TypeParam measured, reference;
  make_plate(measured, 4, 1.0, 0.0);
  make_plate(reference, 7, 3.0, 0.3);  // larger, so every sample is above its interior
  Eigen::MatrixX3d samples;
  const Status sampled = primitive_edit::sample_surface_uniform(measured, 20000, 1, &samples);
  ASSERT_TRUE(sampled.ok()) << sampled.error;
  ASSERT_EQ(samples.rows(), 20000);

  SurfaceDistanceIndex index(reference);
  ASSERT_TRUE(index.status().ok()) << index.status().error;
  AccuracyReport r = primitive_edit::measure_accuracy(samples, index, 0.42, true);
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  EXPECT_EQ(r.sample_count, 20000);
  EXPECT_DOUBLE_EQ(r.within_tolerance_share, 1.0);
  EXPECT_NEAR(r.mean, 0.3, 1e-6);
  EXPECT_NEAR(r.rms, 0.3, 1e-6);
  EXPECT_NEAR(r.max, 0.3, 1e-6);
  ASSERT_EQ(r.distances.size(), 20000);
  EXPECT_NEAR(r.distances.minCoeff(), 0.3, 1e-6);
  // 0.3 / (2 * 0.42 / 10) = 3.57: every sample in bin 3.
  ASSERT_EQ(r.histogram.size(), size_t(primitive_edit::kAccuracyHistogramBins + 1));
  EXPECT_EQ(r.histogram[3], 20000);

  r = primitive_edit::measure_accuracy(samples, index, 0.2);
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  EXPECT_DOUBLE_EQ(r.within_tolerance_share, 0.0);
  EXPECT_EQ(r.histogram[7], 20000);  // 0.3 / (2 * 0.2 / 10) = 7.5
  EXPECT_EQ(r.distances.size(), 0);
}

TYPED_TEST(MeasureAccuracyTest, SphereAgainstLargerSphereMatchesRadialGap)
{
  TypeParam measured, reference;
  make_uv_sphere(measured, 1.0, 60, 120);
  const int stacks = 100, slices = 200;
  make_uv_sphere(reference, 1.1, stacks, slices);
  Eigen::MatrixX3d samples;
  ASSERT_TRUE(primitive_edit::sample_surface_uniform(measured, 5000, 7, &samples).ok());
  ASSERT_EQ(samples.rows(), 5000);
  SurfaceDistanceIndex index(reference);
  ASSERT_TRUE(index.status().ok()) << index.status().error;
  // The poles' degenerate triangles are left out of the index.
  EXPECT_EQ(index.skipped_face_count(), 2 * slices);
  const AccuracyReport r = primitive_edit::measure_accuracy(samples, index, 0.05, true);
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  // The tessellated reference lies between radius 1.1 cos(step) and 1.1 (step = the larger angular step),
  // so each distance is the radial gap 1.1 - |p| up to that sagitta.
  const double step = 2.0 * primitive_edit::kPi / slices;
  const double sagitta = 1.1 * (1.0 - std::cos(step));
  for (Eigen::Index i = 0; i < samples.rows(); ++i)
    ASSERT_NEAR(r.distances(i), 1.1 - samples.row(i).norm(), sagitta + 1e-6) << "sample " << i;
  EXPECT_NEAR(r.mean, 0.1, 2e-3);
  EXPECT_DOUBLE_EQ(r.within_tolerance_share, 0.0);
  const AccuracyReport loose = primitive_edit::measure_accuracy(samples, index, 0.15);
  EXPECT_DOUBLE_EQ(loose.within_tolerance_share, 1.0);
}

TYPED_TEST(MeasureAccuracyTest, GridQueriesMatchBruteForceNearAndFar)
{
  TypeParam reference;
  make_uv_sphere(reference, 1.0, 24, 48);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (auto& v : reference.vert)  // bumpy, so that closest points fall on faces, edges and vertices
    v.P() += typename TypeParam::CoordType(noise(rng), noise(rng), noise(rng));
  SurfaceDistanceIndex index(reference);
  ASSERT_TRUE(index.status().ok()) << index.status().error;

  // Points inside, near and far outside the sphere (the grid spans about [-1, 1]^3).
  std::uniform_real_distribution<double> coord(-3.0, 3.0);
  Eigen::MatrixX3d points(300, 3);
  Eigen::VectorXd expected(points.rows());
  for (Eigen::Index q = 0; q < points.rows(); ++q) {
    const Eigen::Vector3d p(coord(rng), coord(rng), coord(rng));
    points.row(q) = p.transpose();
    double brute = std::numeric_limits<double>::infinity();
    for (const auto& f : reference.face) {
      Eigen::Vector3d c[3];
      for (int k = 0; k < 3; ++k)
        c[k] = Eigen::Vector3d(f.cV(k)->cP()[0], f.cV(k)->cP()[1], f.cV(k)->cP()[2]);
      if ((c[1] - c[0]).cross(c[2] - c[0]).squaredNorm() == 0.0)
        continue;
      brute = std::min(brute, (primitive_edit::closest_point_on_triangle(p, c[0], c[1], c[2]) - p).norm());
    }
    expected(q) = brute;
    // One at a time, in random order: the previous query's triangle is a poor start.
    ASSERT_NEAR(index.distance(p), brute, 1e-12) << "query " << p.transpose();
  }
  // All together, in spatial order.
  Eigen::VectorXd batch;
  ASSERT_TRUE(index.distances(points, batch).ok());
  ASSERT_EQ(batch.size(), points.rows());
  EXPECT_LT((batch - expected).cwiseAbs().maxCoeff(), 1e-12);
  // Any grid density gives the same distances (0.5: tiny cells, capped; 20: a handful of cells).
  for (double factor : {0.5, 20.0}) {
    SurfaceDistanceIndex other(reference, Eigen::Affine3d::Identity(), factor);
    ASSERT_TRUE(other.distances(points, batch).ok());
    EXPECT_LT((batch - expected).cwiseAbs().maxCoeff(), 1e-12) << "cell size factor " << factor;
  }
  points(7, 2) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(index.distances(points, batch).ok());
  EXPECT_EQ(batch.size(), 0);
}

TYPED_TEST(MeasureAccuracyTest, SamplesPerFaceAreProportionalToArea)
{
  TypeParam m;
  // Areas 0.5, 1.5, 3: probabilities 0.1, 0.3, 0.6.
  make_triangles(m, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                     {2, 0, 0}, {5, 0, 0}, {2, 1, 0},
                     {0, 0, 1}, {0, 3, 1}, {0, 0, 3}});
  const Eigen::Index n = 100000;
  Eigen::VectorXi faces;
  Eigen::MatrixX3d s;
  const Status sampled = primitive_edit::sample_surface_uniform(m, n, 11, &s, &faces);
  ASSERT_TRUE(sampled.ok()) << sampled.error;
  ASSERT_EQ(s.rows(), n);
  ASSERT_EQ(faces.size(), n);
  const double p[3] = {0.1, 0.3, 0.6};
  int count[3] = {0, 0, 0};
  int in_corner = 0;  // samples of face 2 in its corner sub-triangle of a quarter of its area
  for (Eigen::Index i = 0; i < n; ++i) {
    ASSERT_GE(faces(i), 0);
    ASSERT_LT(faces(i), 3);
    ++count[faces(i)];
    const auto& f = m.face[size_t(faces(i))];
    Eigen::Vector3d c[3];
    for (int k = 0; k < 3; ++k)
      c[k] = Eigen::Vector3d(f.cV(k)->cP()[0], f.cV(k)->cP()[1], f.cV(k)->cP()[2]);
    const Eigen::Vector3d x = s.row(i).transpose();
    EXPECT_NEAR((x - c[0]).dot((c[1] - c[0]).cross(c[2] - c[0]).normalized()), 0.0, 1e-12);
    const Eigen::Vector3d bary = barycentric(x, c[0], c[1], c[2]);
    ASSERT_GE(bary.minCoeff(), -1e-12) << "sample outside its face";
    if (faces(i) == 2 && bary(0) >= 0.5)
      ++in_corner;
  }
  for (int f = 0; f < 3; ++f) {
    const double expected = n * p[f], sigma = std::sqrt(n * p[f] * (1.0 - p[f]));
    EXPECT_NEAR(count[f], expected, 5.0 * sigma) << "face " << f;
  }
  const double corner_sigma = std::sqrt(count[2] * 0.25 * 0.75);
  EXPECT_NEAR(in_corner, 0.25 * count[2], 5.0 * corner_sigma);
}

TYPED_TEST(MeasureAccuracyTest, SeededSamplingIsReproducible)
{
  TypeParam m;
  make_uv_sphere(m, 2.0, 10, 20);
  Eigen::MatrixX3d a, b, c;
  ASSERT_TRUE(primitive_edit::sample_surface_uniform(m, 1000, 42, &a).ok());
  ASSERT_TRUE(primitive_edit::sample_surface_uniform(m, 1000, 42, &b).ok());
  ASSERT_TRUE(primitive_edit::sample_surface_uniform(m, 1000, 43, &c).ok());
  ASSERT_EQ(a.rows(), 1000);
  EXPECT_TRUE(a == b);
  EXPECT_FALSE(a == c);
}

TYPED_TEST(MeasureAccuracyTest, DegenerateAndNonFiniteFacesAreSkipped)
{
  TypeParam m;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  make_triangles(m, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0},          // collinear: zero area
                     {0, 0, 0}, {nan, 0, 0}, {0, 1, 0},        // NaN vertex
                     {0, 0, 5}, {1, 0, 5}, {0, 1, 5}});        // the only usable face
  Eigen::VectorXi faces;
  Eigen::MatrixX3d s;
  ASSERT_TRUE(primitive_edit::sample_surface_uniform(m, 500, 5, &s, &faces).ok());
  ASSERT_EQ(s.rows(), 500);
  EXPECT_TRUE(s.allFinite());
  EXPECT_TRUE((faces.array() == 2).all());
  EXPECT_TRUE((s.col(2).array() == 5.0).all());

  SurfaceDistanceIndex index(m);
  ASSERT_TRUE(index.status().ok()) << index.status().error;
  EXPECT_EQ(index.triangle_count(), 1);
  EXPECT_EQ(index.skipped_face_count(), 2);
  EXPECT_NEAR(index.distance(Eigen::Vector3d(0.25, 0.25, 0.0)), 5.0, 1e-12);
}

TYPED_TEST(MeasureAccuracyTest, AFlatMeshFarFromTheOriginIsIndexedWithoutCollapsingTheGrid)
{
  // Found by the fuzz target: at z = 1e32 a cell of the plate's size is below the coordinates' precision, so the
  // grid's box had zero height and cell indices were NaN.
  TypeParam far;
  make_plate(far, 4, 300.0, 1e32);
  SurfaceDistanceIndex index(far);
  ASSERT_TRUE(index.status().ok()) << index.status().error;
  const double z = double(far.vert[0].cP()[2]);  // 1e32 as the mesh's scalar stores it
  EXPECT_EQ(index.distance(Eigen::Vector3d(10.0, 20.0, z)), 0.0);
  EXPECT_TRUE(std::isfinite(index.distance(Eigen::Vector3d(1e3, -1e3, z))));
}

TYPED_TEST(MeasureAccuracyTest, BadInputFailsWithAMessage)
{
  TypeParam empty;
  Eigen::MatrixX3d none = Eigen::MatrixX3d::Ones(3, 3);
  Status sampled = primitive_edit::sample_surface_uniform(empty, 10, 0, &none);
  EXPECT_EQ(none.rows(), 0);
  EXPECT_EQ(sampled.error, "the mesh has no faces");

  TypeParam flat;
  make_triangles(flat, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
  sampled = primitive_edit::sample_surface_uniform(flat, 10, 0, &none);
  EXPECT_EQ(none.rows(), 0);
  EXPECT_NE(sampled.error.find("no face with a positive"), std::string::npos) << sampled.error;

  TypeParam plate;
  make_plate(plate, 2, 1.0, 0.0);
  sampled = primitive_edit::sample_surface_uniform(plate, 0, 0, &none);
  EXPECT_EQ(none.rows(), 0);
  EXPECT_NE(sampled.error.find("at least 1"), std::string::npos) << sampled.error;

  const SurfaceDistanceIndex no_faces(empty);
  EXPECT_FALSE(no_faces.status().ok());
  EXPECT_EQ(no_faces.status().error, "the reference mesh has no faces");
  const SurfaceDistanceIndex degenerate(flat);
  EXPECT_FALSE(degenerate.status().ok());
  EXPECT_NE(degenerate.status().error.find("positive area"), std::string::npos) << degenerate.status().error;

  Eigen::MatrixX3d samples;
  ASSERT_TRUE(primitive_edit::sample_surface_uniform(plate, 100, 0, &samples).ok());
  AccuracyReport r = primitive_edit::measure_accuracy(samples, empty, 0.42);
  EXPECT_FALSE(r.status.ok());
  EXPECT_EQ(r.status.error, "the reference mesh has no faces");

  SurfaceDistanceIndex index(plate);
  ASSERT_TRUE(index.status().ok());
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    r = primitive_edit::measure_accuracy(samples, index, bad);
    EXPECT_FALSE(r.status.ok()) << bad;
    EXPECT_NE(r.status.error.find("tolerance"), std::string::npos) << r.status.error;
  }
  Eigen::MatrixX3d with_nan = samples;
  with_nan(5, 1) = std::numeric_limits<double>::quiet_NaN();
  r = primitive_edit::measure_accuracy(with_nan, index, 0.42);
  EXPECT_FALSE(r.status.ok());
  EXPECT_NE(r.status.error.find("NaN"), std::string::npos) << r.status.error;
  r = primitive_edit::measure_accuracy(Eigen::MatrixX3d(0, 3), index, 0.42);
  EXPECT_FALSE(r.status.ok());
  EXPECT_EQ(r.status.error, "there are no sample points");
}

TYPED_TEST(MeasureAccuracyTest, VertexDistancesGiveTheDeviationOfEveryVertex)
{
  TypeParam measured, reference;
  make_plate(measured, 3, 1.0, 0.0);
  make_plate(reference, 5, 4.0, -0.25);
  vcg::tri::Allocator<TypeParam>::DeleteVertex(measured, measured.vert[0]);  // deleted vertices get 0
  SurfaceDistanceIndex index(reference);
  Eigen::VectorXd d;
  Status measured_ok = primitive_edit::vertex_distances(measured, index, d);
  ASSERT_TRUE(measured_ok.ok()) << measured_ok.error;
  ASSERT_EQ(d.size(), Eigen::Index(measured.vert.size()));
  EXPECT_EQ(d(0), 0.0);
  for (Eigen::Index i = 1; i < d.size(); ++i)
    EXPECT_NEAR(d(i), 0.25, 1e-6);

  // The layer transform moves the measured mesh 1.0 up: 1.25 from the reference.
  Eigen::Affine3d up = Eigen::Affine3d::Identity();
  up.translate(Eigen::Vector3d(0, 0, 1.0));
  measured_ok = primitive_edit::vertex_distances(measured, index, d, up);
  ASSERT_TRUE(measured_ok.ok()) << measured_ok.error;
  EXPECT_NEAR(d(4), 1.25, 1e-6);

  measured.vert[3].P()[2] = std::numeric_limits<float>::quiet_NaN();
  measured_ok = primitive_edit::vertex_distances(measured, index, d);
  EXPECT_FALSE(measured_ok.ok());
  EXPECT_NE(measured_ok.error.find("vertex 3"), std::string::npos) << measured_ok.error;
}

TEST(SummarizeAccuracy, ShareMeanRmsMaxAndHistogramFromKnownDistances)
{
  Eigen::VectorXd d(5);
  d << 0.0, 0.1, 0.42, 0.5, 2.0;
  const AccuracyReport r = primitive_edit::summarize_accuracy(d, 0.42);
  ASSERT_TRUE(r.status.ok()) << r.status.error;
  EXPECT_DOUBLE_EQ(r.within_tolerance_share, 3.0 / 5.0);  // 0.42 itself is within
  EXPECT_DOUBLE_EQ(r.mean, 3.02 / 5.0);
  EXPECT_DOUBLE_EQ(r.rms, std::sqrt((0.01 + 0.42 * 0.42 + 0.25 + 4.0) / 5.0));
  EXPECT_DOUBLE_EQ(r.max, 2.0);
  EXPECT_DOUBLE_EQ(r.histogram_bin_width, 0.084);
  // Bins of 0.084: 0.42 / 0.084 = 5 (half-open bins: the tolerance starts bin 5), 0.5 / 0.084 = 5.95.
  const std::vector<Eigen::Index> expected = {1, 1, 0, 0, 0, 2, 0, 0, 0, 0, 1};
  EXPECT_EQ(r.histogram, expected);

  Eigen::VectorXd negative(1);
  negative << -0.1;
  EXPECT_FALSE(primitive_edit::summarize_accuracy(negative, 0.42).status.ok());
}

TEST(ClosestPointOnTriangle, FaceEdgeAndVertexRegions)
{
  const Eigen::Vector3d a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  using primitive_edit::closest_point_on_triangle;
  EXPECT_TRUE(closest_point_on_triangle({0.5, 0.5, 3}, a, b, c).isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
  EXPECT_TRUE(closest_point_on_triangle({1, -1, 1}, a, b, c).isApprox(Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(closest_point_on_triangle({2, 2, 0}, a, b, c).isApprox(Eigen::Vector3d(1, 1, 0)));
  EXPECT_TRUE(closest_point_on_triangle({-1, -1, 0}, a, b, c).isApprox(a));
  EXPECT_TRUE(closest_point_on_triangle({3, -1, 0}, a, b, c).isApprox(b));
  EXPECT_TRUE(closest_point_on_triangle({-0.5, 3, 1}, a, b, c).isApprox(c));
}

} // namespace
