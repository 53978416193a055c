// estimate_surface_roughness: zero on an exact plane, proportional to the noise of a noisy one, zero on bad
// input; and the automatic tolerance of fit_primitive_auto that uses it: a rough segment is a primitive.
#include "test_mesh.h"
#include "test_fit_data.h"

#include "common/base/constants.h"
#include "common/mesh/estimate_surface_roughness.h"
#include "common/mesh/surface_roughness_attribute.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/smooth_face_normals.h"
#include "common/fit/fit_primitive_auto.h"

#include <gtest/gtest.h>

#include <random>

using namespace primitive_edit;

namespace {

// A 100 x 100 grid of unit squares in z = 0, each vertex moved along z by Gaussian noise of std sigma.
void make_noisy_grid(test_mesh::TMesh& m, double sigma, unsigned seed)
{
  constexpr int n = 100;
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  auto vi = vcg::tri::Allocator<test_mesh::TMesh>::AddVertices(m, size_t(n + 1) * size_t(n + 1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j, ++vi)
      vi->P() = test_mesh::TMesh::CoordType(i, j, sigma > 0 ? noise(rng) : 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      auto* a = &m.vert[size_t(i) * (n + 1) + size_t(j)];
      auto* b = &m.vert[size_t(i + 1) * (n + 1) + size_t(j)];
      auto* c = &m.vert[size_t(i + 1) * (n + 1) + size_t(j + 1)];
      auto* d = &m.vert[size_t(i) * (n + 1) + size_t(j + 1)];
      vcg::tri::Allocator<test_mesh::TMesh>::AddFace(m, a, b, c);
      vcg::tri::Allocator<test_mesh::TMesh>::AddFace(m, a, c, d);
    }
}

double roughness_of_grid(double sigma, unsigned seed)
{
  test_mesh::TMesh m;
  make_noisy_grid(m, sigma, seed);
  return estimate_surface_roughness(m, build_face_adjacency(m));
}

// An open cylinder band of radius r as a grid of triangles about 0.1 wide, each vertex moved
// along the normal by Gaussian noise of std sigma.
void make_noisy_cylinder(test_mesh::TMesh& m, double r, double sigma, unsigned seed)
{
  // About 120k faces whatever the radius (at least 40 rows), so that a patch of 1/200 of them holds 600.
  const int nu = int(std::lround(2 * kPi * r / 0.1)), nv = std::max(40, 60000 / nu);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  auto vi = vcg::tri::Allocator<test_mesh::TMesh>::AddVertices(m, size_t(nu) * size_t(nv + 1));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j <= nv; ++j, ++vi) {
      const double a = 2 * kPi * i / nu, rr = r + (sigma > 0 ? noise(rng) : 0.0);
      vi->P() = test_mesh::TMesh::CoordType(rr * std::cos(a), rr * std::sin(a), 0.1 * j);
    }
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      auto at = [&](int a, int b) { return &m.vert[size_t(a % nu) * size_t(nv + 1) + size_t(b)]; };
      vcg::tri::Allocator<test_mesh::TMesh>::AddFace(m, at(i, j), at(i + 1, j), at(i + 1, j + 1));
      vcg::tri::Allocator<test_mesh::TMesh>::AddFace(m, at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
}

} // namespace

TEST(EstimateSurfaceRoughness, NoiseOnCylindersDoesNotGrowWithCurvature)
{
  // A patch of 600 faces is about 2.5 mm across: a plane's RMS about it grows as the radius shrinks (on radius
  // 1.5 it is about 0.03, twice the noise), a quadric's is the noise on every radius. The centroid's noise is
  // sigma / sqrt(3).
  const double sigma = 0.03;
  for (double r : {1.5, 4.0, 30.0}) {
    test_mesh::TMesh m;
    make_noisy_cylinder(m, r, sigma, 7);
    const FaceCentroidsAndAreas faces = face_centroids_and_areas(m);
    const SurfaceRoughness s = measure_surface_roughness(faces.centroid, faces.area, build_face_adjacency(m));
    EXPECT_GT(s.noise, 0.8 * sigma / std::sqrt(3.0)) << "radius " << r;
    EXPECT_LT(s.noise, 1.2 * sigma / std::sqrt(3.0)) << "radius " << r;
    EXPECT_LE(s.roughness, kMedianPatchSmoothRatio * s.noise * (1 + 1e-12)) << "radius " << r;
    EXPECT_GE(s.waviness, s.noise) << "radius " << r;
  }
  // Without noise: a height-field quadric follows a circle to fourth order, so on radius 4 (patches of about
  // 36 degrees of arc) the estimate is a small fraction of the noise above; on radius 1.5 (95 degrees) it
  // reads about 0.003.
  test_mesh::TMesh exact;
  make_noisy_cylinder(exact, 4.0, 0.0, 8);
  const FaceCentroidsAndAreas faces = face_centroids_and_areas(exact);
  EXPECT_LT(measure_surface_roughness(faces.centroid, faces.area, build_face_adjacency(exact)).noise,
            0.1 * sigma / std::sqrt(3.0));
}

// Threads share the patches and the faces, never a result: every thread count gives the same figures, bit for
// bit (120k faces: the face tables, the adjacency and normal smoothing split them between threads). Some faces are
// deleted, so that the ranges hold faces that link nothing.
TEST(EstimateSurfaceRoughness, SameOnEveryThreadCount)
{
  test_mesh::TMesh m;
  make_noisy_cylinder(m, 4.0, 0.03, 9);
  for (std::size_t f = 0; f < m.face.size(); f += 997)
    vcg::tri::Allocator<test_mesh::TMesh>::DeleteFace(m, m.face[f]);
  const FaceAdjacency adj = build_face_adjacency(m, 1);
  std::vector<Eigen::Vector3d> raw_one;
  const FaceCentroidsAndAreas faces = face_centroids_and_areas(m, 1, &raw_one);
  const SurfaceRoughness one = measure_surface_roughness(faces.centroid, faces.area, adj, 0, 1);
  const std::vector<Eigen::Vector3d> normals_one = smooth_face_normals(m, adj, 5, 180.0, 1);
  for (int threads : {2, 3, 8}) {
    const FaceAdjacency adj_many = build_face_adjacency(m, threads);
    EXPECT_TRUE(adj_many.offset == adj.offset && adj_many.neighbour == adj.neighbour) << threads << " threads";
    std::vector<Eigen::Vector3d> raw_many;
    const FaceCentroidsAndAreas faces_many = face_centroids_and_areas(m, threads, &raw_many);
    EXPECT_TRUE(faces_many.centroid == faces.centroid && faces_many.area == faces.area && raw_many == raw_one)
        << threads << " threads";
    const SurfaceRoughness many = measure_surface_roughness(faces.centroid, faces.area, adj, 0, threads);
    EXPECT_EQ(many.noise, one.noise) << threads << " threads";
    EXPECT_EQ(many.waviness, one.waviness) << threads << " threads";
    EXPECT_EQ(many.roughness, one.roughness) << threads << " threads";
    EXPECT_TRUE(smooth_face_normals(m, adj, 5, 180.0, threads) == normals_one) << threads << " threads";
  }
  EXPECT_GT(one.noise, 0.0);
  // The normals beside the table: the face's unit normal from its corners, zero for a deleted face, whose
  // neighbours do not list it.
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    if (m.face[f].IsD()) {
      EXPECT_TRUE(raw_one[f].isZero(0.0) && faces.area[f] == 0.0) << f;
      EXPECT_EQ(adj.offset[f], adj.offset[f + 1]) << f;
      continue;
    }
    const vcg::Point3d n = vcg::TriangleNormal(m.face[f]).Normalize();
    EXPECT_LT((raw_one[f] - Eigen::Vector3d(n[0], n[1], n[2])).norm(), 1e-12) << f;
  }
  for (int g : adj.neighbour)
    EXPECT_FALSE(m.face[std::size_t(g)].IsD()) << g;
}

TEST(EstimateSurfaceRoughness, ExactPlaneIsSmooth)
{
  EXPECT_LT(roughness_of_grid(0.0, 1), 1e-12);
}

TEST(EstimateSurfaceRoughness, NoisyPlaneGivesTheNoiseOfItsFaceCentroids)
{
  // A centroid averages three vertices: its noise is sigma / sqrt(3) about the plane.
  const double sigma = 0.05;
  const double r = roughness_of_grid(sigma, 2);
  EXPECT_GT(r, 0.8 * sigma / std::sqrt(3.0));
  EXPECT_LT(r, 1.2 * sigma / std::sqrt(3.0));
  EXPECT_NEAR(roughness_of_grid(2 * sigma, 3) / r, 2.0, 0.2);
}

TEST(QuadricPatchRms, IsTheRmsOfTheLeastSquaresQuadricOverThePcaPlane)
{
  // The moments the fit sums must give the residuals of the dense least-squares height field, weighted, with
  // the 6 parameters taken from the degrees of freedom.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> at(-1.5, 1.5), weight(0.2, 2.0);
  std::normal_distribution<double> noise(0.0, 0.02);
  const Eigen::Index n = 500;
  Eigen::MatrixX3d points(n, 3);
  Eigen::VectorXd weights(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = at(rng), y = 0.5 * at(rng);
    points.row(i) << 10 + x, -3 + y, 7 + 0.3 * x * x - 0.2 * x * y + 0.1 * y + noise(rng);
    weights[i] = weight(rng);
  }
  const WeightedPca pca = weighted_pca(points, weights);
  const Eigen::MatrixX3d local = (points.rowwise() - pca.centroid.transpose()) * pca.axes;
  Eigen::MatrixXd rows(n, 6);
  rows << local.col(2).array().square(), local.col(2).array() * local.col(1).array(), local.col(1).array().square(),
      local.col(2), local.col(1), Eigen::VectorXd::Ones(n);
  const Eigen::VectorXd root = weights.cwiseSqrt();
  const Eigen::VectorXd c = (root.asDiagonal() * rows).colPivHouseholderQr().solve(root.asDiagonal() * local.col(0));
  const Eigen::VectorXd r = local.col(0) - rows * c;
  const double expected = std::sqrt(weights.dot(r.cwiseAbs2()) / weights.sum() * double(n) / double(n - 6));
  EXPECT_NEAR(quadric_patch_rms(points, weights, pca), expected, 1e-9 * expected);
  EXPECT_GT(expected, 0.015);  // the noise, not the curvature, is left
  EXPECT_LT(expected, 0.025);
}

TEST(EstimateSurfaceRoughness, PatchesSkipUnusableFaces)
{
  // Faces of zero area take no part: patches grow around them, and the noise is that of the rest.
  test_mesh::TMesh m;
  make_noisy_grid(m, 0.05, 12);
  const FaceAdjacency adj = build_face_adjacency(m);
  const FaceCentroidsAndAreas faces = face_centroids_and_areas(m);
  std::vector<double> area = faces.area;
  for (std::size_t f = 0; f < area.size(); f += 3)
    area[f] = 0.0;
  const double all = estimate_surface_roughness(faces.centroid, faces.area, adj);
  const double some = estimate_surface_roughness(faces.centroid, area, adj);
  EXPECT_GT(some, 0.8 * all);
  EXPECT_LT(some, 1.2 * all);
  std::vector<double> none(area.size(), 0.0);
  EXPECT_EQ(estimate_surface_roughness(faces.centroid, none, adj), 0.0);
}

TEST(EstimateSurfaceRoughness, BadInputGivesZero)
{
  test_mesh::TMesh empty;
  EXPECT_EQ(estimate_surface_roughness(empty, build_face_adjacency(empty)), 0.0);
  test_mesh::TMesh m;
  make_noisy_grid(m, 0.05, 4);
  EXPECT_EQ(estimate_surface_roughness(m, FaceAdjacency()), 0.0);  // adjacency of another mesh
  for (auto& v : m.vert)
    v.P()[2] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(estimate_surface_roughness(m, build_face_adjacency(m)), 0.0);
}

TEST(AutoFitTolerance, ARoughSegmentIsAPrimitiveWhenTheRoughnessIsKnown)
{
  // A plane patch of size 2 with noise of 5% of its size: over the default 1% of the size it is free-form,
  // within 3x a roughness of that noise it is a plane.
  using namespace test_fit;
  Sample s = sample_primitive(make_plane({0, 0, 0}, {0, 0, 1}), Patch(), 2000, 5);
  add_noise(&s, 0.1, 2.0, 6);
  const AutoFitResult unknown = fit_primitive_auto(s.points, s.normals, Eigen::VectorXd());
  EXPECT_FALSE(unknown.status.ok());
  AutoFitOptions options;
  options.roughness = 0.1;
  const AutoFitResult known = fit_primitive_auto(s.points, s.normals, Eigen::VectorXd(), options);
  ASSERT_TRUE(known.status.ok()) << known.status.error;
  EXPECT_EQ(known.best.primitive.type, PrimitiveType::Plane);
  // A roughness that is not a number is unknown, not an infinite tolerance that every type would meet.
  for (double broken : {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    options.roughness = broken;
    EXPECT_FALSE(fit_primitive_auto(s.points, s.normals, Eigen::VectorXd(), options).status.ok()) << broken;
  }
}

TEST(SurfaceRoughnessAttribute, KeptUntilAVertexMoves)
{
  test_mesh::TMesh m;
  make_noisy_grid(m, 0.05, 9);
  EXPECT_FALSE(read_surface_roughness(m).has_value());
  const double measured = surface_roughness(m, build_face_adjacency(m));
  EXPECT_GT(measured, 0.0);
  ASSERT_TRUE(read_surface_roughness(m).has_value());
  EXPECT_EQ(*read_surface_roughness(m), measured);
  EXPECT_EQ(surface_roughness(m), measured);  // kept: no adjacency needed
  write_surface_roughness(m, 0.5);  // a later filter's own figure replaces it
  EXPECT_EQ(surface_roughness(m, build_face_adjacency(m)), 0.5);
  m.vert[17].P()[2] += 0.01f;       // the mesh has changed: measured again
  EXPECT_FALSE(read_surface_roughness(m).has_value());
  EXPECT_NEAR(surface_roughness(m, build_face_adjacency(m)), measured, 0.01 * measured);
}
