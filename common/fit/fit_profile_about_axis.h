// fit_profile_about_axis.h: the surface of revolution of a given type about a given axis that best fits points.
//
// Input:  points N x 3, weights N (empty = all 1), an axis (a point and a unit direction) and a type: cylinder,
//         cone, sphere or torus.
// Output: the primitive of that type whose axis (a sphere: whose centre) lies on the given axis, or std::nullopt
//         when the points do not fix one (fewer points of positive weight than its parameters, points on a line of
//         the profile for a circle, a cone's line parallel or perpendicular to the axis: a cylinder or a plane).
// Method: in the meridian half-plane (r = distance from the axis, h = height along it) a surface of revolution is
//         a curve, and a point's distance to the surface is its distance to that curve: a cylinder is r = R
//         (1 parameter), a cone a line (2), a sphere a circle centred on the axis (2), a torus any circle (3).
//         The cylinder's R is the mean r and the cone's line the principal direction of the (r, h) points, both
//         least squares already; the circles start from closed forms (Kasa's with the centre on the axis,
//         Taubin's, fit_circle_2d.h) and take Gauss-Newton steps on the distances to the circle.
// Cost:   O(N) per step, at most kProfileIterations steps.
#ifndef PRIMITIVE_EDIT_FIT_PROFILE_ABOUT_AXIS_H
#define PRIMITIVE_EDIT_FIT_PROFILE_ABOUT_AXIS_H

#include "common/base/primitive.h"

#include <Eigen/Core>

#include <optional>

namespace primitive_edit {

constexpr int kProfileIterations = 20;

// The parameters of each type's profile about a given axis (0 for a plane: not a profile this fits).
constexpr int profile_degrees_of_freedom(PrimitiveType type)
{
  switch (type) {
  case PrimitiveType::Cylinder: return 1;
  case PrimitiveType::Cone: return 2;
  case PrimitiveType::Sphere: return 2;
  case PrimitiveType::Torus: return 3;
  case PrimitiveType::Plane: return 0;
  }
  return 0;
}

std::optional<Primitive> fit_profile_about_axis(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                                                const Eigen::Vector3d& axis_point, const Eigen::Vector3d& axis,
                                                PrimitiveType type);

} // namespace primitive_edit

#endif
