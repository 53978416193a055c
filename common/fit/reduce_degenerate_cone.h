// reduce_degenerate_cone.h: a cone that does not taper over its data is a cylinder.
//
// Input:  a fit (FitResult) of points N x 3 with weights N (empty = all 1), the distance tolerance, and the options
//         of the cylinder's refinement.
// Output: cone_is_cylinder_within: whether the cone's radius changes by at most the tolerance along the points of
//         positive weight (its axial extent times tan(half angle)); such a cone is no more than the cylinder within
//         the tolerance. reduce_degenerate_cone: for a cone fit that is, the cylinder refined on the same points;
//         any other fit, or a cylinder whose refinement fails, comes back unchanged.
// Method: fit_primitive_auto refuses such a cone when it chooses a type; a cone refined on more of the data (a
//         growing region, a union tested for a merge) can still run towards the cylinder, its half angle to 0 and
//         its apex thousands of radii away, a limit it never reaches (on the 4M bracket scan 82% of the cones'
//         Levenberg-Marquardt runs ended on their iteration cap, bench/README.md). The cylinder starts on the
//         cone's axis, at the points' mean height and mean distance from it.
// Cost:   O(N) for the test and the start, plus the cylinder's refinement (refine_primitive.h).
#ifndef PRIMITIVE_EDIT_REDUCE_DEGENERATE_CONE_H
#define PRIMITIVE_EDIT_REDUCE_DEGENERATE_CONE_H

#include "common/fit/fit_result.h"

#include <Eigen/Core>

namespace primitive_edit {

// Extent of the points (w > 0) along the axis: the length over which a cone's taper is seen.
double axial_extent(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, const Eigen::Vector3d& axis);

bool cone_is_cylinder_within(const Primitive& cone, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                             double tolerance);

FitResult reduce_degenerate_cone(const FitResult& fit, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                                 double tolerance, const FitOptions& options);

} // namespace primitive_edit

#endif
