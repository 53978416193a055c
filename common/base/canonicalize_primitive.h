// canonicalize_primitive.h: puts a fitted primitive into the output conventions of the fits.
//
// Input:  a valid primitive and the points (N x 3) with weights (N, empty = all 1) it was fitted to.
// Output: the same surface with: plane origin = weighted centroid projected onto the plane;
//         cylinder origin = the axis point closest to the weighted centroid; cone axis pointing from
//         the apex into the opening with half angle in (0, pi/2) (already guaranteed by the
//         parametrisation, only the axis is re-normalised); sphere and torus unchanged apart from a
//         unit axis. Axis signs of plane, cylinder and torus are left as they are (the caller orients
//         them, e.g. the plane normal along the given normals, or with largest_component_positive, the
//         convention of a fit without normals: the axis's largest component positive, the first of a tie).
// Cost:   O(N).
#ifndef PRIMITIVE_EDIT_CANONICALIZE_PRIMITIVE_H
#define PRIMITIVE_EDIT_CANONICALIZE_PRIMITIVE_H

#include "common/base/primitive.h"

namespace primitive_edit {

Primitive canonicalize_primitive(Primitive p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights);

inline Eigen::Vector3d largest_component_positive(const Eigen::Vector3d& axis)
{
  Eigen::Index k = 0;
  axis.cwiseAbs().maxCoeff(&k);
  return axis[k] < 0 ? Eigen::Vector3d(-axis) : axis;
}

} // namespace primitive_edit

#endif
