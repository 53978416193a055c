// constants.h: the numbers the core names once: pi and the degree/radian conversions.
//
// Input:  angles in degrees or radians. Output: the same angle in the other unit. Cost: none.
// Users type angles in degrees (MeshLab's parameters, the edit tool's fields); the core works in radians.
#ifndef PRIMITIVE_EDIT_CONSTANTS_H
#define PRIMITIVE_EDIT_CONSTANTS_H

namespace primitive_edit {

constexpr double kPi = 3.14159265358979323846;

constexpr double radians_from_degrees(double degrees) { return degrees * (kPi / 180.0); }
constexpr double degrees_from_radians(double radians) { return radians * (180.0 / kPi); }

} // namespace primitive_edit

#endif
