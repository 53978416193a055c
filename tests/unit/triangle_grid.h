// triangle_grid.h: a test surface for the core's array-based mesh code: an nx x ny grid of unit squares, two
// triangles each, counter-clockwise seen from +z, as vertex positions, face_vertex and VertexFaces. A vertex at
// x >= fold_at is raised by (x - fold_at), so the surface bends by 45 degrees along x = fold_at (none by default).
#ifndef PRIMITIVE_EDIT_TEST_TRIANGLE_GRID_H
#define PRIMITIVE_EDIT_TEST_TRIANGLE_GRID_H

#include "common/mesh/vertex_faces.h"

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace grid_fixture {

struct TriangleGrid
{
  int nx, ny;
  std::vector<Eigen::Vector3d> points;
  std::vector<int> face_vertex;
  primitive_edit::VertexFaces vertex_faces;

  TriangleGrid(int nx_, int ny_, double fold_at = std::numeric_limits<double>::infinity()) : nx(nx_), ny(ny_)
  {
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        points.emplace_back(i, j, std::max(0.0, i - fold_at));
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const int v : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1)})
          face_vertex.push_back(v);
    vertex_faces = primitive_edit::build_vertex_faces(face_vertex, points.size());
  }
  int id(int i, int j) const { return j * (nx + 1) + i; }
  int faces() const { return int(face_vertex.size() / 3); }
  const Eigen::Vector3d& corner(int f, int k) const
  {
    return points[std::size_t(face_vertex[3 * std::size_t(f) + std::size_t(k)])];
  }
  Eigen::Vector3d centroid(int f) const { return (corner(f, 0) + corner(f, 1) + corner(f, 2)) / 3; }
};

} // namespace grid_fixture

#endif
