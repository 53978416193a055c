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

inline AxialExtent axial_extent(const Eigen::MatrixX3d& points, const Eigen::Vector3d& origin,
                                const Eigen::Vector3d& d, double size)
{
  AxialExtent e{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                Eigen::Vector3d::Zero()};
  int count = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d q = points.row(i).transpose();
    if (!q.allFinite())
      continue;
    const double h = (q - origin).dot(d);
    e.lo = std::min(e.lo, h);
    e.hi = std::max(e.hi, h);
    e.centroid += q;
    ++count;
  }
  if (count == 0)
    return {-size, size, origin};
  e.centroid /= count;
  return e;
}

// A 6 x 6 grid in the plane of normal d through origin, over the square around the points' projection.
inline void plane_grid(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::Vector3d& d,
                       const Eigen::Vector3d& u, const Eigen::Vector3d& v, const Eigen::Vector3d& centroid,
                       double size, Lines& lines)
{
  const Eigen::Vector3d c = centroid - (centroid - p.origin).dot(d) * d;
  double reach = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d q = points.row(i).transpose();
    if (q.allFinite())
      reach = std::max({reach, std::abs((q - c).dot(u)), std::abs((q - c).dot(v))});
  }
  if (!(reach > 0))
    reach = size;
  for (int i = 0; i <= 5; ++i) {
    const double t = -reach + 2.0 * reach * i / 5;
    lines.line(c + t * u - reach * v, c + t * u + reach * v);
    lines.line(c - reach * u + t * v, c + reach * u + t * v);
  }
}

} // namespace wireframe_detail

inline Eigen::MatrixX3d primitive_wireframe(const Primitive& p, const Eigen::MatrixX3d& points, int pieces = 48)
{
  using namespace wireframe_detail;
  if (!primitive_is_valid(p))
    return Eigen::MatrixX3d(0, 3);
  Lines lines{std::clamp(pieces, 8, 256), {}};
  const Eigen::Vector3d d = p.type == PrimitiveType::Sphere ? Eigen::Vector3d::UnitZ() : p.axis.normalized();
  const Eigen::Vector3d u = any_orthogonal(d);
  const Eigen::Vector3d v = d.cross(u);
  const double size = p.radius > 0 ? p.radius : 1.0;
  const AxialExtent h = axial_extent(points, p.origin, d, size);

  switch (p.type) {
  case PrimitiveType::Plane:
    plane_grid(p, points, d, u, v, h.centroid, size, lines);
    break;
  case PrimitiveType::Sphere:
    lines.circle(p.origin, u, v, p.radius);
    lines.circle(p.origin, u, d, p.radius);
    lines.circle(p.origin, v, d, p.radius);
    for (double s : {-0.5, 0.5})
      lines.circle(p.origin + s * p.radius * d, u, v, p.radius * std::sqrt(0.75));
    break;
  case PrimitiveType::Cylinder:
    for (int i = 0; i <= 4; ++i)
      lines.circle(p.origin + (h.lo + (h.hi - h.lo) * i / 4) * d, u, v, p.radius);
    for (int i = 0; i < 12; ++i) {
      const Eigen::Vector3d r = p.radius * Lines::around(i, 12, u, v);
      lines.line(p.origin + h.lo * d + r, p.origin + h.hi * d + r);
    }
    break;
  case PrimitiveType::Cone: {
    // Only the nappe the axis points into exists.
    const double lo = std::max(h.lo, 0.0), hi = std::max(h.hi, lo);
    const double slope = std::tan(p.half_angle);
    for (int i = 0; i <= 4; ++i) {
      const double z = lo + (hi - lo) * i / 4;
      lines.circle(p.origin + z * d, u, v, z * slope);
    }
    for (int i = 0; i < 12; ++i) {
      const Eigen::Vector3d dir = Lines::around(i, 12, u, v);
      lines.line(p.origin + lo * (d + slope * dir), p.origin + hi * (d + slope * dir));
    }
    break;
  }
  case PrimitiveType::Torus:
    lines.circle(p.origin, u, v, p.radius + p.minor_radius);
    lines.circle(p.origin, u, v, std::max(p.radius - p.minor_radius, 0.0));
    lines.circle(p.origin + p.minor_radius * d, u, v, p.radius);
    for (int i = 0; i < 12; ++i) {
      const Eigen::Vector3d dir = Lines::around(i, 12, u, v);
      lines.circle(p.origin + p.radius * dir, dir, d, p.minor_radius);
    }
    break;
  }

  Eigen::MatrixX3d out(Eigen::Index(lines.ends.size()), 3);
  for (std::size_t i = 0; i < lines.ends.size(); ++i)
    out.row(Eigen::Index(i)) = lines.ends[i].transpose();
  return out;
}

} // namespace primitive_edit

#endif
