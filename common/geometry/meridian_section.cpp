#include "common/geometry/meridian_section.h"

#include "common/base/constants.h"
#include "common/geometry/edge_blend.h"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace primitive_edit {

namespace {

Primitive plane_of_space(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal)
{
  Primitive p;
  p.type = PrimitiveType::Plane;
  p.origin = origin;
  p.axis = normal.normalized();
  return p;
}

} // namespace

std::optional<MeridianFrame> meridian_frame(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                                            const Eigen::Vector3d& towards)
{
  if (!origin.allFinite() || !axis.allFinite() || !towards.allFinite() || !(axis.norm() > 0))
    return std::nullopt;
  MeridianFrame f;
  f.origin = origin;
  f.axis = axis.normalized();
  const Eigen::Vector3d d = towards - f.origin;
  const Eigen::Vector3d radial = d - f.axis * d.dot(f.axis);
  const double r = radial.norm();
  if (!(r > 1e-12 * std::max(1.0, d.norm())))
    return std::nullopt;
  f.first = radial / r;
  f.second = f.axis.cross(f.first);
  f.arc_radius = r;
  return f;
}

Eigen::Vector3d to_meridian(const MeridianFrame& f, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d d = p - f.origin;
  const double x = d.dot(f.first), y = d.dot(f.second);
  return Eigen::Vector3d(std::hypot(x, y), d.dot(f.axis), f.arc_radius * std::atan2(y, x));
}

Eigen::Vector3d from_meridian(const MeridianFrame& f, const Eigen::Vector3d& q)
{
  const double angle = q.z() / f.arc_radius;
  return f.origin + q.y() * f.axis + q.x() * (std::cos(angle) * f.first + std::sin(angle) * f.second);
}

double meridian_extent(const MeridianFrame& f, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (!weights.size() || weights[i] > 0) {
      const Eigen::Vector2d q = to_meridian(f, points.row(i).transpose()).head<2>();
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
  return (hi - lo).allFinite() ? (hi - lo).norm() : 0.0;
}

std::optional<Primitive> meridian_of_turned(const MeridianFrame& f, const Primitive& turned)
{
  if ((turned.type != PrimitiveType::Cylinder && turned.type != PrimitiveType::Cone) || !primitive_is_valid(turned))
    return std::nullopt;
  // (r, h): a cylinder is r = R; a cone, apex at h0 and opening along +-axis, the line r = (h - h0) tan(angle).
  if (turned.type == PrimitiveType::Cylinder)
    return plane_of_space(Eigen::Vector3d(turned.radius, 0, 0), Eigen::Vector3d::UnitX());
  const double opening = turned.axis.dot(f.axis) < 0 ? -1.0 : 1.0;
  return plane_of_space(Eigen::Vector3d(0, (turned.origin - f.origin).dot(f.axis), 0),
                        Eigen::Vector3d(std::cos(turned.half_angle), -opening * std::sin(turned.half_angle), 0));
}

std::optional<Primitive> meridian_of_plane(const MeridianFrame& f, const Primitive& plane, const Eigen::Vector3d& near)
{
  if (plane.type != PrimitiveType::Plane || !primitive_is_valid(plane) || !near.allFinite())
    return std::nullopt;
  const double cosine = plane.axis.dot(f.axis);
  if (!(std::abs(cosine) >= std::sin(radians_from_degrees(kMinBlendAngleDeg))))
    return std::nullopt;
  const Eigen::Vector3d foot = near - plane.axis * (near - plane.origin).dot(plane.axis);
  return plane_of_space(Eigen::Vector3d(0, (foot - f.origin).dot(f.axis), 0), Eigen::Vector3d::UnitY());
}

std::optional<Primitive> revolve(const MeridianFrame& f, const Primitive& blend)
{
  Primitive p;
  if (blend.type == PrimitiveType::Cylinder) {
    // A fillet's circle, centre (R, h) and tube radius.
    p.type = PrimitiveType::Torus;
    p.origin = f.origin + blend.origin.y() * f.axis;
    p.axis = f.axis;
    p.radius = blend.origin.x();
    p.minor_radius = blend.radius;
  } else if (blend.type == PrimitiveType::Plane) {
    // A chamfer's line n.(r, h) = c.
    const double nr = blend.axis.x(), nh = blend.axis.y();
    const double c = nr * blend.origin.x() + nh * blend.origin.y();
    const double length = std::hypot(nr, nh);
    if (!(length > 0))
      return std::nullopt;
    if (std::abs(nh) <= 1e-12 * length) {
      p.type = PrimitiveType::Cylinder;
      p.origin = f.origin;
      p.axis = f.axis;
      p.radius = c / nr;
    } else if (std::abs(nr) <= 1e-12 * length) {
      p.type = PrimitiveType::Plane;
      p.origin = f.origin + (c / nh) * f.axis;
      p.axis = f.axis;
    } else {
      // The line meets the axis at h = c / nh; along (-nh, nr), turned to widen, r grows as h moves by dh.
      Eigen::Vector2d along(-nh, nr);
      if (along.x() < 0)
        along = -along;
      p.type = PrimitiveType::Cone;
      p.origin = f.origin + (c / nh) * f.axis;
      p.axis = along.y() >= 0 ? f.axis : Eigen::Vector3d(-f.axis);
      p.half_angle = std::atan2(along.x(), std::abs(along.y()));
    }
  } else {
    return std::nullopt;
  }
  if (!primitive_is_valid(p))
    return std::nullopt;
  return p;
}

} // namespace primitive_edit
