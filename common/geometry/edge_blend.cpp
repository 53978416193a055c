#include "common/geometry/edge_blend.h"

#include "common/base/constants.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace primitive_edit {

Eigen::Vector3d in_section(const EdgeSection& e, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d q = p - e.origin;
  return q - e.direction * q.dot(e.direction);
}

std::optional<PlanesLine> planes_line(const Primitive& a, const Primitive& b, const Eigen::Vector3d& near)
{
  if (a.type != PrimitiveType::Plane || b.type != PrimitiveType::Plane || !primitive_is_valid(a) ||
      !primitive_is_valid(b) || !near.allFinite())
    return std::nullopt;
  const Eigen::Vector3d direction = a.axis.cross(b.axis);
  const double sine = direction.norm();
  if (!(sine >= std::sin(radians_from_degrees(kMinBlendAngleDeg))))
    return std::nullopt;
  PlanesLine line;
  line.direction = direction / sine;
  Eigen::Matrix3d m;
  m.row(0) = a.axis.transpose();
  m.row(1) = b.axis.transpose();
  m.row(2) = line.direction.transpose();
  line.origin =
      m.partialPivLu().solve(Eigen::Vector3d(a.axis.dot(a.origin), b.axis.dot(b.origin), line.direction.dot(near)));
  if (!line.origin.allFinite())
    return std::nullopt;
  return line;
}

std::optional<EdgeSection> edge_section(const Primitive& a, const Primitive& b, const Eigen::Vector3d& kept_a,
                                        const Eigen::Vector3d& kept_b, const Eigen::Vector3d& near)
{
  if (!kept_a.allFinite() || !kept_b.allFinite())
    return std::nullopt;
  const std::optional<PlanesLine> line = planes_line(a, b, near);
  if (!line)
    return std::nullopt;
  EdgeSection e;
  e.origin = line->origin;
  e.direction = line->direction;
  auto ray = [&](const Primitive& plane, const Eigen::Vector3d& kept) -> std::optional<Eigen::Vector3d> {
    const Eigen::Vector3d r = e.direction.cross(plane.axis).normalized();
    const double side = (kept - e.origin).dot(r);
    if (!(side != 0))
      return std::nullopt;
    return side > 0 ? r : Eigen::Vector3d(-r);
  };
  const std::optional<Eigen::Vector3d> ra = ray(a, kept_a), rb = ray(b, kept_b);
  if (!ra || !rb)
    return std::nullopt;
  e.ray_a = *ra;
  e.ray_b = *rb;
  e.bisector = (e.ray_a + e.ray_b).normalized(); // the rays are at least kMinBlendAngleDeg from opposite
  e.half_angle = 0.5 * std::acos(std::clamp(e.ray_a.dot(e.ray_b), -1.0, 1.0));
  return e;
}

double distance_along(const EdgeSection& e, const Eigen::Vector3d& ray, const Eigen::Vector3d& p)
{
  return (p - e.origin).dot(ray);
}

Primitive edge_blend_primitive(const EdgeSection& e, BlendForm form, double s)
{
  Primitive p;
  if (form == BlendForm::Fillet) {
    p.type = PrimitiveType::Cylinder;
    p.origin = e.origin + e.bisector * (s / std::cos(e.half_angle));
    p.axis = e.direction;
    p.radius = s * std::tan(e.half_angle);
  } else {
    p.type = PrimitiveType::Plane;
    p.origin = e.origin + s * e.ray_a;
    p.axis = e.bisector;
  }
  return p;
}

double edge_blend_distance(const EdgeSection& e, BlendForm form, double s, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d q = in_section(e, p);
  if (form == BlendForm::Fillet)
    return std::abs((q - e.bisector * (s / std::cos(e.half_angle))).norm() - s * std::tan(e.half_angle));
  return std::abs(q.dot(e.bisector) - s * std::cos(e.half_angle));
}

bool in_edge_blend_sector(const EdgeSection& e, double s, const Eigen::Vector3d& p)
{
  const Eigen::Vector3d q = in_section(e, p);
  return q.dot(e.ray_a) < s && q.dot(e.ray_b) < s;
}

} // namespace primitive_edit
