// Tests of common/mesh/locate_on_surface.h (the walk that keeps a slid vertex on the scan).
#include "common/mesh/locate_on_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using namespace primitive_edit;

// An n x n grid of unit squares in z = 0, two triangles each (counter-clockwise seen from +z); a vertex with
// x >= fold_at is raised by (x - fold_at), so the surface bends by 45 degrees along x = fold_at.
struct SquareGrid
{
  std::vector<Eigen::Vector3d> points;
  std::vector<int> face_vertex;
  VertexFaces vertex_faces;

  SquareGrid(int n, double fold_at = 1e9)
  {
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        points.emplace_back(i, j, std::max(0.0, i - fold_at));
    auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const int v : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1)})
          face_vertex.push_back(v);
    vertex_faces = build_vertex_faces(face_vertex, points.size());
  }
  int faces() const { return int(face_vertex.size() / 3); }
  Eigen::Vector3d centroid(int f) const
  {
    return (points[std::size_t(face_vertex[3 * std::size_t(f)])] + points[std::size_t(face_vertex[3 * std::size_t(f) + 1])] +
            points[std::size_t(face_vertex[3 * std::size_t(f) + 2])]) /
           3;
  }
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
  const SurfaceLocation fenced = grid.locate(0, Eigen::Vector3d(3.5, 1.5, 0), [&](int f) { return grid.centroid(f).x() < 2; });
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
