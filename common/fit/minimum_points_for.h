// minimum_points_for.h: the fewest points (with positive weight) a fit of a given type accepts.
//
// Input: a primitive type. Output: a point count, one or two more than the type's degrees of freedom
// so that a fit is over-determined and an exact-looking fit to too few points is not reported.
// Cost: O(1).
#ifndef PRIMITIVE_EDIT_MINIMUM_POINTS_FOR_H
#define PRIMITIVE_EDIT_MINIMUM_POINTS_FOR_H

#include "common/base/primitive.h"

namespace primitive_edit {

inline int minimum_points_for(PrimitiveType type)
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

#endif
