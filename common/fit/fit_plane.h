// fit_plane.h: least-squares plane through points.
//
// Input:  points N x 3 (N >= 3), normals N x 3 or empty, weights N or empty (= all 1), options.
// Output: FitResult with a Plane: origin = weighted centroid (of the inliers) projected onto the plane,
//         axis = unit normal, oriented along the sum of the given normals when there are normals,
//         otherwise with its largest component positive. A failed status for bad input or collinear points.
// Method: the weighted PCA plane (smallest principal axis) is the exact orthogonal least-squares
//         plane; refine_best_start.h then only adds the robust reweighting (on a 2000-point
//         subsample first for large inputs, then on all points).
// Cost:   O(N) per reweighting round.
#ifndef PRIMITIVE_EDIT_FIT_PLANE_H
#define PRIMITIVE_EDIT_FIT_PLANE_H

#include "common/base/canonicalize_primitive.h"
#include "common/fit/check_fit_input.h"
#include "common/fit/minimum_points_for.h"
#include "common/fit/fit_subsample.h"
#include "common/fit/refine_best_start.h"
#include "common/geometry/weighted_pca.h"

namespace primitive_edit {

FitResult fit_plane(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                    const Eigen::VectorXd& weights, const FitOptions& options = {});

} // namespace primitive_edit

#endif
