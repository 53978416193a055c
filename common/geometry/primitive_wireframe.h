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

#include "common/geometry/closest_point_on_primitive.h"
#include "common/base/primitive.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace primitive_edit {

inline Eigen::MatrixX3d primitive_wireframe(const Primitive& p, const Eigen::MatrixX3d& points, int pieces = 48)
{
  if (!primitive_is_valid(p))
    return Eigen::MatrixX3d(0, 3);
  pieces = std::clamp(pieces, 8, 256);
  const double two_pi = 6.283185307179586;
  const Eigen::Vector3d d = p.type == PrimitiveType::Sphere ? Eigen::Vector3d::UnitZ() : p.axis.normalized();
  const Eigen::Vector3d u = any_orthogonal(d);
  const Eigen::Vector3d v = d.cross(u);

  std::vector<Eigen::Vector3d> ends;
  auto line = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    ends.push_back(a);
    ends.push_back(b);
  };
  // Circle of radius r around centre c in the plane spanned by unit vectors e1, e2.
  auto circle = [&](const Eigen::Vector3d& c, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, double r) {
    for (int i = 0; i < pieces; ++i) {
      const double t0 = two_pi * i / pieces, t1 = two_pi * (i + 1) / pieces;
      line(c + r * (std::cos(t0) * e1 + std::sin(t0) * e2), c + r * (std::cos(t1) * e1 + std::sin(t1) * e2));
    }
  };

  // Extent of the finite points along the axis (from the origin) and in the plane's directions.
  double h_lo = std::numeric_limits<double>::infinity(), h_hi = -h_lo, reach = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  int count = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d q = points.row(i).transpose();
    if (!q.allFinite())
      continue;
    const double h = (q - p.origin).dot(d);
    h_lo = std::min(h_lo, h);
    h_hi = std::max(h_hi, h);
    centroid += q;
    ++count;
  }
  const double size = p.radius > 0 ? p.radius : 1.0;
  if (count == 0) {
    h_lo = -size;
    h_hi = size;
    centroid = p.origin;
  } else {
    centroid /= count;
  }

  switch (p.type) {
  case PrimitiveType::Plane: {
    const Eigen::Vector3d c = centroid - (centroid - p.origin).dot(d) * d;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
      const Eigen::Vector3d q = points.row(i).transpose();
      if (q.allFinite())
        reach = std::max({reach, std::abs((q - c).dot(u)), std::abs((q - c).dot(v))});
    }
    if (!(reach > 0))
      reach = size;
    for (int i = 0; i <= 5; ++i) {
      const double t = -reach + 2.0 * reach * i / 5;
      line(c + t * u - reach * v, c + t * u + reach * v);
      line(c - reach * u + t * v, c + reach * u + t * v);
    }
    break;
  }
  case PrimitiveType::Sphere:
    circle(p.origin, u, v, p.radius);
    circle(p.origin, u, d, p.radius);
    circle(p.origin, v, d, p.radius);
    for (double s : {-0.5, 0.5})
      circle(p.origin + s * p.radius * d, u, v, p.radius * std::sqrt(0.75));
    break;
  case PrimitiveType::Cylinder:
    for (int i = 0; i <= 4; ++i)
      circle(p.origin + (h_lo + (h_hi - h_lo) * i / 4) * d, u, v, p.radius);
    for (int i = 0; i < 12; ++i) {
      const Eigen::Vector3d r = p.radius * (std::cos(two_pi * i / 12) * u + std::sin(two_pi * i / 12) * v);
      line(p.origin + h_lo * d + r, p.origin + h_hi * d + r);
    }
    break;
  case PrimitiveType::Cone: {
    // Only the nappe the axis points into exists.
    const double lo = std::max(h_lo, 0.0), hi = std::max(h_hi, lo);
    const double slope = std::tan(p.half_angle);
    for (int i = 0; i <= 4; ++i) {
      const double h = lo + (hi - lo) * i / 4;
      circle(p.origin + h * d, u, v, h * slope);
    }
    for (int i = 0; i < 12; ++i) {
      const Eigen::Vector3d dir = std::cos(two_pi * i / 12) * u + std::sin(two_pi * i / 12) * v;
      line(p.origin + lo * (d + slope * dir), p.origin + hi * (d + slope * dir));
    }
    break;
  }
  case PrimitiveType::Torus:
    circle(p.origin, u, v, p.radius + p.minor_radius);
    circle(p.origin, u, v, std::max(p.radius - p.minor_radius, 0.0));
    circle(p.origin + p.minor_radius * d, u, v, p.radius);
    for (int i = 0; i < 12; ++i) {
      const Eigen::Vector3d dir = std::cos(two_pi * i / 12) * u + std::sin(two_pi * i / 12) * v;
      circle(p.origin + p.radius * dir, dir, d, p.minor_radius);
    }
    break;
  }

  Eigen::MatrixX3d out(Eigen::Index(ends.size()), 3);
  for (std::size_t i = 0; i < ends.size(); ++i)
    out.row(Eigen::Index(i)) = ends[i].transpose();
  return out;
}

} // namespace primitive_edit

#endif
