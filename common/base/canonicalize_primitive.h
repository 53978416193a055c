// canonicalize_primitive.h: puts a fitted primitive into the output conventions of the fits.
//
// Input:  a valid primitive and the points (N x 3) with weights (N, empty = all 1) it was fitted to.
// Output: the same surface with: plane origin = weighted centroid projected onto the plane;
//         cylinder origin = the axis point closest to the weighted centroid; cone axis pointing from
//         the apex into the opening with half angle in (0, pi/2) (already guaranteed by the
//         parametrisation, only the axis is re-normalised); sphere and torus unchanged apart from a
//         unit axis. Axis signs of plane, cylinder and torus are left as they are (the caller orients
//         them, e.g. the plane normal along the given normals).
// Cost:   O(N).
#ifndef PRIMITIVE_EDIT_CANONICALIZE_PRIMITIVE_H
#define PRIMITIVE_EDIT_CANONICALIZE_PRIMITIVE_H

#include "common/base/primitive.h"

namespace primitive_edit {

inline Primitive canonicalize_primitive(Primitive p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
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

#endif
