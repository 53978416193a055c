// Tests of common/mesh/locate_on_surface.h (the walk that keeps a slid vertex on the scan).
#include "common/mesh/locate_on_surface.h"
#include "triangle_grid.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace primitive_edit;

// An n x n TriangleGrid, optionally bent along x = fold_at, and the walk over it.
struct SquareGrid : grid_fixture::TriangleGrid
{
  explicit SquareGrid(int n, double fold_at = std::numeric_limits<double>::infinity()) : TriangleGrid(n, n, fold_at) {}
  template <class Enters>
  SurfaceLocation locate(int start, const Eigen::Vector3d& p, Enters&& enters, int max_steps = 64) const
  {
    return locate_on_surface([this](int v) { return points[std::size_t(v)]; }, face_vertex, vertex_faces, enters,
                             start, p, max_steps);
  }
  SurfaceLocation locate(int start, const Eigen::Vector3d& p) const
  {
    return locate(start, p, [](int) { return true; });
  }
};

TEST(LocateOnSurface, WalksAcrossAFlatGridToTheFaceUnderThePoint)
{
  const SquareGrid grid(10);
  const SurfaceLocation at = grid.locate(0, Eigen::Vector3d(7.3, 8.6, 2.5));
  EXPECT_TRUE(at.point.isApprox(Eigen::Vector3d(7.3, 8.6, 0), 1e-12));
  const Eigen::Vector3d c = grid.centroid(at.face);
  EXPECT_EQ(std::floor(c.x()), 7);
  EXPECT_EQ(std::floor(c.y()), 8);
}

TEST(LocateOnSurface, StopsOnTheBorderAtItsNearestPoint)
{
  const SquareGrid grid(4);
  const SurfaceLocation beyond = grid.locate(0, Eigen::Vector3d(6, 2.5, 1));
  EXPECT_TRUE(beyond.point.isApprox(Eigen::Vector3d(4, 2.5, 0), 1e-12));
  // Only the faces with x < 2 make up the surface: the walk stops on its border at x = 2.
  const SurfaceLocation fenced =
      grid.locate(0, Eigen::Vector3d(3.5, 1.5, 0), [&](int f) { return grid.centroid(f).x() < 2; });
  EXPECT_LT(grid.centroid(fenced.face).x(), 2);
  EXPECT_TRUE(fenced.point.isApprox(Eigen::Vector3d(2, 1.5, 0), 1e-12));
}

TEST(LocateOnSurface, FollowsTheSurfaceOverABend)
{
  const SquareGrid grid(8, 4.0);
  // Above the raised half, 45 degrees up from x = 4: the nearest point is on that half, not on z = 0.
  const Eigen::Vector3d p(6, 3.5, 2 + 0.5);
  const SurfaceLocation at = grid.locate(0, p);
  EXPECT_GT(grid.centroid(at.face).x(), 4);
  EXPECT_NEAR(at.point.z(), at.point.x() - 4, 1e-12);
  const Eigen::Vector3d normal = Eigen::Vector3d(-1, 0, 1).normalized();
  EXPECT_NEAR((p - at.point).cross(normal).norm(), 0, 1e-12) << "the step to the surface is along its normal";
}

TEST(LocateOnSurface, AWalkCutShortEndsOnAFaceOfItsPath)
{
  const SquareGrid grid(20);
  const SurfaceLocation at = grid.locate(0, Eigen::Vector3d(19.5, 19.5, 0), [](int) { return true; }, 3);
  EXPECT_NEAR(at.point.z(), 0, 1e-12);
  // Three faces crossed, then three descents to a face sharing a corner: far from the query, near the start.
  EXPECT_LT(grid.centroid(at.face).norm(), 8.0);
  EXPECT_TRUE(at.point.isApprox(Eigen::Vector3d(at.point.x(), at.point.y(), 0)));
}

TEST(LocateOnSurface, ADegenerateFaceGivesItsNearestCorner)
{
  const std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const std::vector<int> face_vertex = {0, 1, 2};
  const VertexFaces vertex_faces = build_vertex_faces(face_vertex, points.size());
  const SurfaceLocation at = locate_on_surface([&](int v) { return points[std::size_t(v)]; }, face_vertex,
                                               vertex_faces, [](int) { return true; }, 0, Eigen::Vector3d(1.8, 1, 0));
  EXPECT_EQ(at.face, 0);
  EXPECT_TRUE(at.point.isApprox(points[2]));
}

} // namespace
