#include "common/fit/fit_circle_around_axis.h"

namespace primitive_edit {

AxisCircle fit_circle_around_axis(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
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
