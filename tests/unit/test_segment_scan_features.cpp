// Unit tests of segment_by_primitive_growing, with the filter's default parameters, on three features of
// machined parts as a scanner sees them (issue 11): a spherical cap on a plane, a countersink (a 90-degree
// conical pocket with a flat bottom) and two fillets between planes. Each is a height field on a regular
// grid, exact and with Gaussian noise of scan-like size (well below the features, clearly above zero).
// Each CAD surface must come back as its own segment (intersection over union by faces with its best
// segment at least 0.8) with the right primitive type and size: a feature swallowed by its neighbours, cut
// in pieces, or fitted by the wrong type fails. On the tests' mesh type and on MeshLab's CMeshO (float).
#include "common/base/constants.h"
#include "common/base/primitive.h"
#include "common/segment/segment_by_primitive_growing.h"

#include "meshlab_test_mesh.h"
#include "test_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace primitive_edit;

namespace {

// Grid step 0.1 (mean edge 0.11 to 0.13: a 60-face seed patch is 0.6 to 0.7 across, small against every
// feature) and the noise levels: exact, and a scan's (std 0.03, a quarter of an edge).
constexpr double kStep = 0.1;
constexpr double kNoises[] = {0.0, 0.03};
constexpr double kMinIoU = 0.8;

struct Grid
{
  double x0, x1, y0, y1;
};

// The height field z = height(x, y) on the grid, triangulated, each vertex moved along z (the view direction
// of a scanner looking down on the part) by Gaussian noise of a fixed seed; truth[f] = surface(x, y) of the
// face's centroid (the noise moves only z, so this is the noise-free shape's surface there).
template <class M, class Height, class Surface>
void make_height_field(M& m, const Grid& grid, double noise, Height height, Surface surface, std::vector<int>& truth)
{
  using S = typename M::ScalarType;
  m.Clear();
  const int nx = int(std::lround((grid.x1 - grid.x0) / kStep)), ny = int(std::lround((grid.y1 - grid.y0) / kStep));
  std::mt19937 rng(5);
  std::normal_distribution<double> gauss(0.0, noise > 0 ? noise : 1.0);
  auto vi = vcg::tri::Allocator<M>::AddVertices(m, size_t(nx + 1) * size_t(ny + 1));
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j, ++vi) {
      const double x = grid.x0 + kStep * i, y = grid.y0 + kStep * j;
      const double z = height(x, y) + (noise > 0 ? gauss(rng) : 0.0);
      vi->P() = typename M::CoordType(S(x), S(y), S(z));
    }
  auto vertex = [&](int i, int j) { return &m.vert[size_t(i) * size_t(ny + 1) + size_t(j)]; };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      vcg::tri::Allocator<M>::AddFace(m, vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1));
      vcg::tri::Allocator<M>::AddFace(m, vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1));
    }
  truth.clear();
  for (const auto& f : m.face) {
    const auto c = (f.cP(0) + f.cP(1) + f.cP(2)) / 3;
    truth.push_back(surface(double(c[0]), double(c[1])));
  }
}

struct Segmentation
{
  std::vector<int> segment_of_face;
  int K = 0;
  SegmentByPrimitiveGrowingReport report;
};

// The height field built as make_height_field does, segmented at the filter's defaults.
template <class M, class Height, class Surface>
Segmentation segment_height_field(const Grid& grid, double noise, Height height, Surface surface,
                                  std::vector<int>& truth)
{
  M m;
  make_height_field(m, grid, noise, height, surface, truth);
  Segmentation s;
  s.K = segment_by_primitive_growing(m, SegmentByPrimitiveGrowingParams(), s.segment_of_face, &s.report);
  EXPECT_EQ(s.report.primitive_of_segment.size(), size_t(s.K));
  return s;
}

// The primitive of the segment that matches truth surface t best (intersection over union by faces), when
// that match reaches kMinIoU and the primitive is of `type`; otherwise a failure and nothing.
std::optional<Primitive> recovered(const Segmentation& s, const std::vector<int>& truth, int t, PrimitiveType type)
{
  std::vector<int> both(size_t(s.K), 0), in_segment(size_t(s.K), 0);
  int in_truth = 0;
  for (size_t f = 0; f < truth.size(); ++f) {
    const int k = s.segment_of_face[f];
    ++in_segment[size_t(k)];
    if (truth[f] == t)
      ++in_truth, ++both[size_t(k)];
  }
  int best = -1;
  double best_iou = 0;
  for (int k = 0; k < s.K; ++k) {
    const double iou = double(both[size_t(k)]) / double(in_truth + in_segment[size_t(k)] - both[size_t(k)]);
    if (iou > best_iou)
      best = k, best_iou = iou;
  }
  EXPECT_GE(best_iou, kMinIoU) << in_truth << " faces, " << s.K << " segments";
  if (best < 0 || best_iou < kMinIoU || size_t(best) >= s.report.primitive_of_segment.size())
    return std::nullopt;
  const std::optional<Primitive>& p = s.report.primitive_of_segment[size_t(best)];
  EXPECT_TRUE(p.has_value()) << "segment without a primitive";
  if (p) {
    EXPECT_EQ(p->type, type) << primitive_type_name(p->type);
  }
  return p && p->type == type ? p : std::nullopt;
}

// A recovered plane is the true one: normal within 2.6 degrees, and `point` of the true plane within 0.05.
void expect_plane(const std::optional<Primitive>& p, const Eigen::Vector3d& normal, const Eigen::Vector3d& point)
{
  if (!p)
    return;
  EXPECT_GT(std::abs(p->axis.dot(normal)), 0.999) << "normal " << p->axis.transpose();
  EXPECT_LT(std::abs(p->axis.dot(point - p->origin)), 0.05);
}

template <class M>
class ScanFeatureTest : public ::testing::Test {};
using ScanMeshTypes = ::testing::Types<test_mesh::TMesh, test_mesh::MeshLabMesh>;
TYPED_TEST_SUITE(ScanFeatureTest, ScanMeshTypes);

// A sphere of radius 10 cut by the plane z = 0 into a cap 0.46 high over a disc of radius 3 (the radius-10
// cap of a peer benchmark part, which a too loose tolerance let its neighbours swallow): it rises 15 noise
// deviations over a footprint 10 seed patches across and meets the plane at 17.5 degrees, and a plane fits
// each seed patch on it within the noise. 12 x 12, 29k faces. (A flatter cap does not fix its radius within
// 5% for every noise draw; around a steeper one, footprint 3.5 to 5, some draws cut the plane into pieces: a
// plane tangent to the cap's flank grows along its line through the base plane.)
TYPED_TEST(ScanFeatureTest, SphereCapOnPlane)
{
  constexpr double R = 10.0, a = 3.0;
  const double centre_z = -std::sqrt(R * R - a * a);
  auto height = [&](double x, double y) {
    const double r2 = x * x + y * y;
    return r2 < a * a ? centre_z + std::sqrt(R * R - r2) : 0.0;
  };
  auto surface = [&](double x, double y) { return x * x + y * y < a * a ? 1 : 0; };
  for (const double noise : kNoises) {
    SCOPED_TRACE("noise " + std::to_string(noise));
    std::vector<int> truth;
    const Segmentation s = segment_height_field<TypeParam>(Grid{-6, 6, -6, 6}, noise, height, surface, truth);
    {
      SCOPED_TRACE("plane");
      expect_plane(recovered(s, truth, 0, PrimitiveType::Plane), Eigen::Vector3d::UnitZ(), Eigen::Vector3d(5, 5, 0));
    }
    SCOPED_TRACE("cap");
    if (const auto cap = recovered(s, truth, 1, PrimitiveType::Sphere)) {
      EXPECT_NEAR(cap->radius, R, 0.05 * R);
      EXPECT_LT((cap->origin - Eigen::Vector3d(0, 0, centre_z)).norm(), 0.05 * R);
    }
  }
}

// A 90-degree countersink in the plane z = 0: a cone of half-angle 45 degrees from radius 5 at the top down
// to a flat bottom of radius 2 at depth 3 (the cone's apex would be at z = -5). Three surfaces meeting at
// 45 degrees, the cone curved around its axis only (radius 2 to 5 against a seed patch of 0.7). 16 x 16,
// 51k faces. (With a top radius of 4, a few noise draws, and exactly a few mesh extents, leave the cone in
// pieces or give it as a torus.)
TYPED_TEST(ScanFeatureTest, Countersink)
{
  constexpr double top = 5.0, bottom = 2.0;
  auto height = [&](double x, double y) {
    const double r = std::hypot(x, y);
    return r >= top ? 0.0 : r >= bottom ? r - top : bottom - top;
  };
  auto surface = [&](double x, double y) {
    const double r = std::hypot(x, y);
    return r >= top ? 0 : r >= bottom ? 1 : 2;
  };
  for (const double noise : kNoises) {
    SCOPED_TRACE("noise " + std::to_string(noise));
    std::vector<int> truth;
    const Segmentation s = segment_height_field<TypeParam>(Grid{-8, 8, -8, 8}, noise, height, surface, truth);
    {
      SCOPED_TRACE("top plane");
      expect_plane(recovered(s, truth, 0, PrimitiveType::Plane), Eigen::Vector3d::UnitZ(), Eigen::Vector3d(6, 6, 0));
    }
    {
      SCOPED_TRACE("cone");
      if (const auto cone = recovered(s, truth, 1, PrimitiveType::Cone)) {
        EXPECT_NEAR(degrees_from_radians(cone->half_angle), 45.0, 2.0);
        EXPECT_GT(cone->axis.z(), 0.999) << "the cone opens upwards";
        EXPECT_LT((cone->origin - Eigen::Vector3d(0, 0, -top)).norm(), 0.2) << "apex";
      }
    }
    SCOPED_TRACE("bottom plane");
    expect_plane(recovered(s, truth, 2, PrimitiveType::Plane), Eigen::Vector3d::UnitZ(),
                 Eigen::Vector3d(0, 0, bottom - top));
  }
}

// A profile extruded along y, all at 45 degrees to the grid so that it stays a height field: a rising
// plane, a convex fillet of radius 2 over a ridge, a falling plane 4 wide, a concave fillet of radius 2 in a
// valley, a rising plane. Each fillet turns by 90 degrees between perpendicular planes and is 2.8 wide (4
// seed patches); near each tangent line the fillet is within the noise of its plane. 20 x 10, 40k faces.
// (A fillet turning by only 45 degrees, from z = 0 to a 45-degree slope, is taken for a plane at radius 2,
// and at radius 6 to 10 still shares less than 0.8 with its segment in a third to half of the noise draws.)
TYPED_TEST(ScanFeatureTest, FilletsBetweenPlanes)
{
  constexpr double R = 2.0, slope_width = 4.0;
  const double half = std::sqrt(0.5);
  const Eigen::Vector3d rising(-half, 0, half), falling(half, 0, half); // the planes' normals
  const double x1 = R / half;                                           // end of the ridge
  const double x2 = x1 + slope_width, z2 = -slope_width;                // start of the valley
  const double x3 = x2 + R / half;                                      // end of the valley
  const Eigen::Vector3d ridge(R * half, 0, -R * half), valley(x2 + R * half, 0, z2 + R * half); // the axes
  auto height = [&](double x, double) {
    if (x < 0)
      return x;
    if (x < x1)
      return ridge.z() + std::sqrt(R * R - (x - ridge.x()) * (x - ridge.x()));
    if (x < x2)
      return x1 - x;
    if (x < x3)
      return valley.z() - std::sqrt(R * R - (x - valley.x()) * (x - valley.x()));
    return z2 + (x - x3);
  };
  auto surface = [&](double x, double) { return x < 0 ? 0 : x < x1 ? 1 : x < x2 ? 2 : x < x3 ? 3 : 4; };
  for (const double noise : kNoises) {
    SCOPED_TRACE("noise " + std::to_string(noise));
    std::vector<int> truth;
    const Segmentation s = segment_height_field<TypeParam>(Grid{-5, 15, 0, 10}, noise, height, surface, truth);
    {
      SCOPED_TRACE("first plane");
      expect_plane(recovered(s, truth, 0, PrimitiveType::Plane), rising, Eigen::Vector3d(-2, 5, -2));
    }
    {
      SCOPED_TRACE("falling plane");
      expect_plane(recovered(s, truth, 2, PrimitiveType::Plane), falling, Eigen::Vector3d(x1, 5, 0));
    }
    {
      SCOPED_TRACE("last plane");
      expect_plane(recovered(s, truth, 4, PrimitiveType::Plane), rising, Eigen::Vector3d(x3, 5, z2));
    }
    for (const int fillet : {1, 3}) {
      SCOPED_TRACE(fillet == 1 ? "ridge fillet" : "valley fillet");
      if (const auto cylinder = recovered(s, truth, fillet, PrimitiveType::Cylinder)) {
        EXPECT_NEAR(cylinder->radius, R, 0.1 * R);
        EXPECT_GT(std::abs(cylinder->axis.y()), 0.999) << "the fillet runs along y";
        const Eigen::Vector3d axis_point = fillet == 1 ? ridge : valley;
        EXPECT_LT(std::hypot(cylinder->origin.x() - axis_point.x(), cylinder->origin.z() - axis_point.z()), 0.1 * R);
      }
    }
  }
}

} // namespace
