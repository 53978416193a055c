// fit_plane_direct.h: the paper's direct (algebraic, type-constrained) plane fit, without refinement.
//
// Input:  points N x 3 (N >= 3), weights N or empty (= all 1).
// Output: FitResult with a Plane: origin = weighted centroid, unit normal with its largest component
//         positive; rms / max_residual / point_count of the orthogonal distances of all points of
//         positive weight. A failed status for bad input (check_fit_input.h) and collinear points.
// Method: Andrews & Sequin's plane type: the quadric's quadratic part is constrained to A = 0, so
//         f = b . x + c; Taubin's normalisation |grad f|^2 = |b|^2 = 1 makes the algebraic distance the
//         orthogonal one and the fit the smallest eigenvector of the weighted covariance (weighted_pca.h),
//         with c through the centroid. It is therefore also the geometric least-squares plane.
// Cost:   O(N) plus a 3 x 3 eigen decomposition.
#ifndef PRIMITIVE_EDIT_FIT_PLANE_DIRECT_H
#define PRIMITIVE_EDIT_FIT_PLANE_DIRECT_H

#include "common/fit/quadric_direct_common.h"

namespace primitive_edit {

FitResult fit_plane_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights = {});

} // namespace primitive_edit

#endif
