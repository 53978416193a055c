// describe_primitive.h: a primitive's parameters in the user's terms, as one line of text for logs.
//
// Input:  a primitive. Output: e.g. "Cylinder: axis point (1, 2, 3), axis (0, 0, 1), radius 4.8,
//         diameter 9.6". Angles in degrees. Cost: O(1).
#ifndef PRIMITIVE_EDIT_DESCRIBE_PRIMITIVE_H
#define PRIMITIVE_EDIT_DESCRIBE_PRIMITIVE_H

#include "common/base/constants.h"
#include "common/base/primitive.h"

#include <cstdio>
#include <string>

namespace primitive_edit {

std::string describe_primitive(const Primitive& p);

} // namespace primitive_edit

#endif
