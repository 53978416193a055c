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

inline AxisCircle fit_circle_around_axis(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                                         const Eigen::Vector3d& axis)
{
  AxisCircle out;
  const Eigen::Vector3d e1 = any_orthogonal(axis), e2 = axis.cross(e1);
  Eigen::MatrixX2d q(points.rows(), 2);
  double height = 0, sum_w = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d p = points.row(i).transpose();
    q(i, 0) = p.dot(e1);
    q(i, 1) = p.dot(e2);
    const double w = weights.size() ? weights[i] : 1.0;
    height += w * p.dot(axis);
    sum_w += w;
  }
  if (!(sum_w > 0))
    return out;
  const Circle2d c = fit_circle_2d(q, weights);
  if (!c.ok)
    return out;
  out.centre = c.centre.x() * e1 + c.centre.y() * e2 + (height / sum_w) * axis;
  out.radius = c.radius;
  out.ok = out.centre.allFinite();
  return out;
}

} // namespace primitive_edit

#endif
