#include "common/base/canonicalize_primitive.h"

namespace primitive_edit {

Primitive canonicalize_primitive(Primitive p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  const double len = p.axis.norm();
  if (len > 0)
    p.axis /= len;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double sum_w = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    if (w > 0) {
      centroid += w * points.row(i).transpose();
      sum_w += w;
    }
  }
  if (!(sum_w > 0))
    return p;
  centroid /= sum_w;
  const Eigen::Vector3d v = centroid - p.origin;
  if (p.type == PrimitiveType::Plane)
    p.origin = centroid - v.dot(p.axis) * p.axis;
  else if (p.type == PrimitiveType::Cylinder)
    p.origin += v.dot(p.axis) * p.axis;
  return p;
}

} // namespace primitive_edit
