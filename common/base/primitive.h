// primitive.h: the analytic surfaces a segment can be given, in the user's terms.
//
// Plane:    `origin` is a point of the plane, `axis` its unit normal; offset = axis.dot(origin).
// Sphere:   `origin` is the centre, `radius` the radius.
// Cylinder: `origin` is a point of the axis, `axis` the unit direction, `radius` the radius.
// Cone:     `origin` is the apex, `axis` the unit direction from the apex into the opening,
//           `half_angle` the angle between axis and surface, in radians, in (0, pi/2). One nappe only.
// Torus:    `origin` is the centre, `axis` the unit axis of revolution, `radius` the major radius
//           (centre to tube centre), `minor_radius` the tube radius.
#ifndef PRIMITIVE_EDIT_PRIMITIVE_H
#define PRIMITIVE_EDIT_PRIMITIVE_H

#include <Eigen/Core>

#include <cmath>

namespace primitive_edit {

enum class PrimitiveType { Plane, Sphere, Cylinder, Cone, Torus };

constexpr int kPrimitiveTypeCount = 5;

struct Primitive
{
  PrimitiveType type = PrimitiveType::Plane;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double radius = 0.0;
  double minor_radius = 0.0;
  double half_angle = 0.0;
};

const char* primitive_type_name(PrimitiveType type);

// Number of free parameters of each type (used to penalise richer models when choosing a type, and as the size
// of the refinement's normal equations, at compile time).
constexpr int primitive_degrees_of_freedom(PrimitiveType type)
{
  switch (type) {
  case PrimitiveType::Plane: return 3;
  case PrimitiveType::Sphere: return 4;
  case PrimitiveType::Cylinder: return 5;
  case PrimitiveType::Cone: return 6;
  case PrimitiveType::Torus: return 7;
  }
  return 0;
}

// True when every number of the primitive is finite and its sizes and axis are valid for its type.
bool primitive_is_valid(const Primitive& p);

} // namespace primitive_edit

#endif
