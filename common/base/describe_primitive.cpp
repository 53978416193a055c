#include "common/base/describe_primitive.h"

namespace primitive_edit {

std::string describe_primitive(const Primitive& p)
{
  auto vec = [](const Eigen::Vector3d& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v.x(), v.y(), v.z());
    return std::string(buf);
  };
  auto num = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return std::string(buf);
  };
  switch (p.type) {
  case PrimitiveType::Plane:
    return "Plane: normal " + vec(p.axis) + ", offset " + num(p.axis.dot(p.origin)) + ", point " + vec(p.origin);
  case PrimitiveType::Sphere:
    return "Sphere: centre " + vec(p.origin) + ", radius " + num(p.radius);
  case PrimitiveType::Cylinder:
    return "Cylinder: axis point " + vec(p.origin) + ", axis " + vec(p.axis) + ", radius " + num(p.radius) +
           ", diameter " + num(2 * p.radius);
  case PrimitiveType::Cone:
    return "Cone: apex " + vec(p.origin) + ", axis " + vec(p.axis) + ", half-angle " +
           num(degrees_from_radians(p.half_angle)) + " deg";
  case PrimitiveType::Torus:
    return "Torus: centre " + vec(p.origin) + ", axis " + vec(p.axis) + ", major radius " + num(p.radius) +
           ", minor radius " + num(p.minor_radius);
  }
  return "Unknown primitive";
}

} // namespace primitive_edit
