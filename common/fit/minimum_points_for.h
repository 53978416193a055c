// minimum_points_for.h: the fewest points (with positive weight) a fit of a given type accepts.
//
// Input: a primitive type. Output: a point count, one or two more than the type's degrees of freedom
// so that a fit is over-determined and an exact-looking fit to too few points is not reported.
// Cost: O(1).
#ifndef PRIMITIVE_EDIT_MINIMUM_POINTS_FOR_H
#define PRIMITIVE_EDIT_MINIMUM_POINTS_FOR_H

#include "common/base/primitive.h"

namespace primitive_edit {

int minimum_points_for(PrimitiveType type);

} // namespace primitive_edit

#endif
