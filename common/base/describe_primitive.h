// describe_primitive.h: a primitive's parameters in the user's terms, as one line of text for logs.
//
// Input:  a primitive. Output: e.g. "Cylinder: axis point (1, 2, 3), axis (0, 0, 1), radius 4.8,
//         diameter 9.6". Angles in degrees. A fit's round-off reads as 0 (shown_value): an axis of
//         (-6.98e-17, 5.98e-17, 1) is written (0, 0, 1). Cost: O(1).
#ifndef PRIMITIVE_EDIT_DESCRIBE_PRIMITIVE_H
#define PRIMITIVE_EDIT_DESCRIBE_PRIMITIVE_H

#include "common/base/constants.h"
#include "common/base/primitive.h"

#include <cstdio>
#include <string>

namespace primitive_edit {

std::string describe_primitive(const Primitive& p);

// What a reader is shown of a parameter: x, or 0 when x is within 1e-12 of `scale` of zero, which no measurement
// resolves and a reader would take for a value. `scale` is 1 for an axis (a unit vector), and
// primitive_size(p) for positions.
double shown_value(double x, double scale);
// The largest of |origin| and the radii: the size a position of p is compared with.
double primitive_size(const Primitive& p);

} // namespace primitive_edit

#endif
