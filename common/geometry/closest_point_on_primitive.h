// closest_point_on_primitive.h: orthogonal projection of a point onto a primitive, with the signed
// distance and the unit surface normal there.
//
// Input:  a valid primitive (see primitive.h) and a point p.
// Output: the closest surface point, the signed distance (positive on the side the normal points to:
//         along the plane normal, outside sphere, cylinder, cone and torus tube) and the outward unit
//         normal at the closest point. Where the closest point is not unique (p on a cylinder axis,
//         at a sphere centre, on the torus axis) one of them is returned, deterministically.
// Cost:   O(1).
#ifndef PRIMITIVE_EDIT_CLOSEST_POINT_ON_PRIMITIVE_H
#define PRIMITIVE_EDIT_CLOSEST_POINT_ON_PRIMITIVE_H

#include "common/base/primitive.h"

#include <Eigen/Geometry>

#include <cmath>

namespace primitive_edit {

struct PrimitiveProjection
{
  Eigen::Vector3d point;
  Eigen::Vector3d normal;
  double signed_distance;
};

// A unit vector orthogonal to the unit vector d.
inline Eigen::Vector3d any_orthogonal(const Eigen::Vector3d& d)
{
  const Eigen::Vector3d helper =
      std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return d.cross(helper).normalized();
}

// Unit radial direction of v away from the unit axis d; any orthogonal direction when v lies on it.
inline Eigen::Vector3d radial_direction(const Eigen::Vector3d& v, const Eigen::Vector3d& d, double* length)
{
  const Eigen::Vector3d q = v - v.dot(d) * d;
  const double n = q.norm();
  if (length)
    *length = n;
  return n > 1e-300 ? Eigen::Vector3d(q / n) : any_orthogonal(d);
}

inline PrimitiveProjection project_onto_primitive(const Primitive& prim, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d& d = prim.axis;
  const Eigen::Vector3d v = p - prim.origin;
  PrimitiveProjection out;
  switch (prim.type) {
  case PrimitiveType::Plane: {
    out.signed_distance = v.dot(d);
    out.point = p - out.signed_distance * d;
    out.normal = d;
    break;
  }
  case PrimitiveType::Sphere: {
    const double n = v.norm();
    out.normal = n > 1e-300 ? Eigen::Vector3d(v / n) : Eigen::Vector3d::UnitZ();
    out.point = prim.origin + prim.radius * out.normal;
    out.signed_distance = n - prim.radius;
    break;
  }
  case PrimitiveType::Cylinder: {
    double rho = 0;
    const Eigen::Vector3d u = radial_direction(v, d, &rho);
    out.normal = u;
    out.point = prim.origin + v.dot(d) * d + prim.radius * u;
    out.signed_distance = rho - prim.radius;
    break;
  }
  case PrimitiveType::Cone: {
    // In the half-plane through the axis and p, the nappe is the ray from the apex along
    // g = (cos a, sin a) in (axial, radial) coordinates, with outward normal (-sin a, cos a).
    double rho = 0;
    const Eigen::Vector3d u = radial_direction(v, d, &rho);
    const double h = v.dot(d);
    const double c = std::cos(prim.half_angle), s = std::sin(prim.half_angle);
    const double t = h * c + rho * s;
    const Eigen::Vector3d generator = c * d + s * u;
    out.normal = -s * d + c * u;
    if (t > 0) {
      out.point = prim.origin + t * generator;
      out.signed_distance = -h * s + rho * c;
    } else {
      out.point = prim.origin;
      out.signed_distance = v.norm();
    }
    break;
  }
  case PrimitiveType::Torus: {
    const Eigen::Vector3d u = radial_direction(v, d, nullptr);
    const Eigen::Vector3d ring = prim.origin + prim.radius * u;
    const Eigen::Vector3d w = p - ring;
    const double n = w.norm();
    out.normal = n > 1e-300 ? Eigen::Vector3d(w / n) : u;
    out.point = ring + prim.minor_radius * out.normal;
    out.signed_distance = n - prim.minor_radius;
    break;
  }
  }
  return out;
}

inline Eigen::Vector3d closest_point_on_primitive(const Primitive& prim, const Eigen::Vector3d& p)
{
  return project_onto_primitive(prim, p).point;
}

inline double signed_distance_to_primitive(const Primitive& prim, const Eigen::Vector3d& p)
{
  return project_onto_primitive(prim, p).signed_distance;
}

} // namespace primitive_edit

#endif
