#include "common/base/describe_primitive.h"

#include <algorithm>
#include <cmath>

namespace primitive_edit {

double shown_value(double x, double scale)
{
  return std::abs(x) <= 1e-12 * scale ? 0.0 : x;
}

double primitive_size(const Primitive& p)
{
  return std::max({p.origin.norm(), std::abs(p.radius), std::abs(p.minor_radius)});
}

std::string describe_primitive(const Primitive& p)
{
  const double size = primitive_size(p);
  auto vec = [](const Eigen::Vector3d& v, double scale) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", shown_value(v.x(), scale), shown_value(v.y(), scale),
                  shown_value(v.z(), scale));
    return std::string(buf);
  };
  auto position = [&](const Eigen::Vector3d& v) { return vec(v, size); };
  auto direction = [&](const Eigen::Vector3d& v) { return vec(v, 1.0); };
  auto num = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return std::string(buf);
  };
  switch (p.type) {
  case PrimitiveType::Plane:
    return "Plane: normal " + direction(p.axis) + ", offset " + num(shown_value(p.axis.dot(p.origin), size)) +
           ", point " + position(p.origin);
  case PrimitiveType::Sphere:
    return "Sphere: centre " + position(p.origin) + ", radius " + num(p.radius);
  case PrimitiveType::Cylinder:
    return "Cylinder: axis point " + position(p.origin) + ", axis " + direction(p.axis) + ", radius " + num(p.radius) +
           ", diameter " + num(2 * p.radius);
  case PrimitiveType::Cone:
    return "Cone: apex " + position(p.origin) + ", axis " + direction(p.axis) + ", half-angle " +
           num(degrees_from_radians(p.half_angle)) + " deg";
  case PrimitiveType::Torus:
    return "Torus: centre " + position(p.origin) + ", axis " + direction(p.axis) + ", major radius " + num(p.radius) +
           ", minor radius " + num(p.minor_radius);
  }
  return "Unknown primitive";
}

} // namespace primitive_edit
