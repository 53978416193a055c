// fit_circle_around_axis.h: where an axis of given direction runs through a point set, and the radius
// of the points around it.
//
// Input:  points N x 3, weights N (empty = all 1), a unit axis direction.
// Output: the points projected onto the plane orthogonal to the axis are fitted with a circle
//         (fit_circle_2d.h); centre = that circle's centre lifted back to 3D at the weighted mean
//         height of the points, radius = its radius. ok == false when the projection is (nearly) a
//         line. Used to place cylinder, cone and torus axes once their direction is guessed.
// Cost:   O(N).
#ifndef PRIMITIVE_EDIT_FIT_CIRCLE_AROUND_AXIS_H
#define PRIMITIVE_EDIT_FIT_CIRCLE_AROUND_AXIS_H

#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/fit_circle_2d.h"

namespace primitive_edit {

struct AxisCircle
{
  bool ok = false;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0;
};

AxisCircle fit_circle_around_axis(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                                  const Eigen::Vector3d& axis);

} // namespace primitive_edit

#endif
