#include "common/fit/minimum_points_for.h"

namespace primitive_edit {

int minimum_points_for(PrimitiveType type)
{
  switch (type) {
  case PrimitiveType::Plane: return 3;
  case PrimitiveType::Sphere: return 4;
  case PrimitiveType::Cylinder: return 6;
  case PrimitiveType::Cone: return 7;
  case PrimitiveType::Torus: return 8;
  }
  return 3;
}

} // namespace primitive_edit
