// primitive_wireframe.h: a few lines that show a primitive where a segment lies, for drawing over the mesh.
//
// Input:  a valid primitive (see primitive.h), the segment's points N x 3 (they bound the drawing of
//         unbounded surfaces: plane, cylinder, cone) and the number of line pieces per circle (clamped to
//         8..256).
// Output: line segments as an M x 3 matrix, rows 2i and 2i+1 being the ends of segment i:
//         plane:    a 6 x 6 grid over the points' extent in the plane (the square around their projection);
//         sphere:   three great circles and two latitudes;
//         cylinder: five circles spread over the points' axial extent and twelve straight lines along it;
//         cone:     five circles over the points' extent along the axis (from the apex) and twelve lines
//                   from the apex side to the opening side;
//         torus:    three circles around the axis (outer, inner, top of the tube) and twelve tube circles.
//         An empty matrix for an invalid primitive. With no finite points the drawing spans the primitive's
//         own size (radius, or 1 for a plane) around its origin.
// Cost:   O(N + pieces).
#ifndef PRIMITIVE_EDIT_PRIMITIVE_WIREFRAME_H
#define PRIMITIVE_EDIT_PRIMITIVE_WIREFRAME_H

#include "common/base/constants.h"
#include "common/base/primitive.h"
#include "common/geometry/closest_point_on_primitive.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace primitive_edit {

namespace wireframe_detail {

// Line segments as pairs of ends, and circles of `pieces` segments.
struct Lines
{
  int pieces;
  std::vector<Eigen::Vector3d> ends;

  void line(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
  {
    ends.push_back(a);
    ends.push_back(b);
  }
  // Circle of radius r around centre c in the plane spanned by unit vectors e1, e2.
  void circle(const Eigen::Vector3d& c, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, double r)
  {
    for (int i = 0; i < pieces; ++i) {
      const double t0 = 2 * kPi * i / pieces, t1 = 2 * kPi * (i + 1) / pieces;
      line(c + r * (std::cos(t0) * e1 + std::sin(t0) * e2), c + r * (std::cos(t1) * e1 + std::sin(t1) * e2));
    }
  }
  // Unit direction i of n around the axis d (u, v: an orthonormal basis of the plane square to it).
  static Eigen::Vector3d around(int i, int n, const Eigen::Vector3d& u, const Eigen::Vector3d& v)
  {
    return std::cos(2 * kPi * i / n) * u + std::sin(2 * kPi * i / n) * v;
  }
};

// The finite points' extent along d from origin and their centroid; without any, +-size about origin.
struct AxialExtent
{
  double lo, hi;
  Eigen::Vector3d centroid;
};

AxialExtent axial_extent(const Eigen::MatrixX3d& points, const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& d, double size);

// A 6 x 6 grid in the plane of normal d through origin, over the square around the points' projection.
void plane_grid(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::Vector3d& d,
                const Eigen::Vector3d& u, const Eigen::Vector3d& v, const Eigen::Vector3d& centroid,
                double size, Lines& lines);

} // namespace wireframe_detail

Eigen::MatrixX3d primitive_wireframe(const Primitive& p, const Eigen::MatrixX3d& points, int pieces = 48);

} // namespace primitive_edit

#endif
