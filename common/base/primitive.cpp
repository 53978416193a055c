#include "common/base/primitive.h"

namespace primitive_edit {

const char* primitive_type_name(PrimitiveType type)
{
  switch (type) {
  case PrimitiveType::Plane: return "Plane";
  case PrimitiveType::Sphere: return "Sphere";
  case PrimitiveType::Cylinder: return "Cylinder";
  case PrimitiveType::Cone: return "Cone";
  case PrimitiveType::Torus: return "Torus";
  }
  return "Unknown";
}

bool primitive_is_valid(const Primitive& p)
{
  if (!p.origin.allFinite() || !p.axis.allFinite() || !std::isfinite(p.radius) ||
      !std::isfinite(p.minor_radius) || !std::isfinite(p.half_angle))
    return false;
  const bool unit_axis = std::abs(p.axis.norm() - 1.0) < 1e-6;
  switch (p.type) {
  case PrimitiveType::Plane: return unit_axis;
  case PrimitiveType::Sphere: return p.radius > 0;
  case PrimitiveType::Cylinder: return unit_axis && p.radius > 0;
  case PrimitiveType::Cone: return unit_axis && p.half_angle > 0 && p.half_angle < 1.5707963267948966;
  case PrimitiveType::Torus: return unit_axis && p.radius > 0 && p.minor_radius > 0;
  }
  return false;
}

} // namespace primitive_edit
