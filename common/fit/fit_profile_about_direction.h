// fit_profile_about_direction.h: the surface of revolution of a given type whose axis has a given direction, its
// position fitted.
//
// Input:  points N x 3, weights N (empty = all 1), a unit direction and a type: plane, cylinder, cone or torus (a
//         sphere has no direction).
// Output: the primitive of that type whose axis (a plane: normal) is parallel to the direction and passes where the
//         points put it, or std::nullopt when they do not fix one (as fit_profile_about_axis.h: too few points, a
//         profile on a line of it, and points whose projection along the direction holds no circle). A plane is the
//         one through the points' weighted mean.
// Method: variable projection (Golub and Pereyra). For an axis through a point c of the plane across the
//         direction, the profile's own 1 to 3 parameters are fitted in the meridian half-plane
//         (fit_profile_about_axis.h); what is left is the 2 coordinates of c. They start at the centre of the circle
//         that the points projected along the direction make (fit_circle_2d.h: a cylinder's own axis, and a band's
//         about its axis), and take Levenberg-Marquardt steps on the points' distances to the surface. As the profile
//         is refitted at every c, the derivatives are those of the reduced problem; they are taken by forward
//         differences.
// Cost:   O(N x profile iterations) per evaluation, 3 evaluations per step, at most kDirectionIterations steps.
#ifndef PRIMITIVE_EDIT_FIT_PROFILE_ABOUT_DIRECTION_H
#define PRIMITIVE_EDIT_FIT_PROFILE_ABOUT_DIRECTION_H

#include "common/base/primitive.h"
#include "common/fit/fit_profile_about_axis.h"

#include <Eigen/Core>

#include <optional>

namespace primitive_edit {

constexpr int kDirectionIterations = 20;

// The parameters of each type with its direction given: a plane's offset; the axis's 2 coordinates across the
// direction and the profile's (fit_profile_about_axis.h). 0 for a sphere, which has no direction.
constexpr int direction_degrees_of_freedom(PrimitiveType type)
{
  return type == PrimitiveType::Plane    ? 1
         : type == PrimitiveType::Sphere ? 0
                                         : 2 + profile_degrees_of_freedom(type);
}

std::optional<Primitive> fit_profile_about_direction(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                                                     const Eigen::Vector3d& direction, PrimitiveType type);

} // namespace primitive_edit

#endif
