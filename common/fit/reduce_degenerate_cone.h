// reduce_degenerate_cone.h: a cone that does not taper over its data is a cylinder; one that does not bend over
// it is a plane.
//
// Input:  a fit (FitResult) of points N x 3 with weights N (empty = all 1), the distance tolerance, and the options
//         of the cylinder's refinement.
// Output: cone_is_cylinder_within: whether the cone's radius changes by at most the tolerance along the points of
//         positive weight (its axial extent times tan(half angle)); such a cone is no more than the cylinder within
//         the tolerance. cone_is_plane_within: whether the cone's surface where the points lie (their projections
//         onto it) stands off its own best plane by at most the tolerance. reduce_degenerate_cone: for a cone fit
//         that is a plane, the plane fitted to the same points; else for one that is a cylinder, the cylinder
//         refined on them; any other fit, or a reduction whose fit fails, comes back unchanged.
// Method: fit_primitive_auto refuses such a cone when it chooses a type; a cone refined on more of the data (a
//         growing region, a union tested for a merge) can still run towards the cylinder, its half angle to 0 and
//         its apex thousands of radii away, a limit it never reaches (on the 4M bracket scan 82% of the cones'
//         Levenberg-Marquardt runs ended on their iteration cap, bench/README.md). The cylinder starts on the
//         cone's axis, at the points' mean height and mean distance from it. Or it runs towards a plane, its half
//         angle to 90 degrees or its apex far off: the bundled bracket scan's bottom, grown and merged as a plane,
//         became a cone of 53 degrees with its apex 540 mm away, 0.84 mm from flat over the bottom at a tolerance
//         of 0.96 mm, and as a cone it had no edges with the walls for the fillets and chamfers between them.
// Cost:   O(N) for the tests and the start, plus the plane's fit or the cylinder's refinement (refine_primitive.h).
#ifndef PRIMITIVE_EDIT_REDUCE_DEGENERATE_CONE_H
#define PRIMITIVE_EDIT_REDUCE_DEGENERATE_CONE_H

#include "common/fit/fit_result.h"

#include <Eigen/Core>

namespace primitive_edit {

// Extent of the points (w > 0) along the axis: the length over which a cone's taper is seen.
double axial_extent(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, const Eigen::Vector3d& axis);

bool cone_is_cylinder_within(const Primitive& cone, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                             double tolerance);

bool cone_is_plane_within(const Primitive& cone, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                          double tolerance);

FitResult reduce_degenerate_cone(const FitResult& fit, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                                 double tolerance, const FitOptions& options);

} // namespace primitive_edit

#endif
