// fit_sphere_direct.h: the paper's direct (algebraic, type-constrained) sphere fit, without refinement.
//
// Input:  points N x 3 (N >= 4), weights N or empty (= all 1).
// Output: FitResult with a Sphere (origin = centre, radius); rms / max_residual / point_count of the
//         orthogonal distances of all points of positive weight. A failed status for bad input
//         (check_fit_input.h), collinear or coplanar points, and a radius above 1e4 times the data's
//         extent (nearly planar points).
// Method: Andrews & Sequin's sphere type: A = a I, i.e. f = a |x|^2 + b . x + c, with Taubin's
//         (= Pratt's, for spheres) normalisation: the same solve as fit_sphere's first start
//         (fit_sphere_detail::taubin_sphere, a 4 x 4 eigenproblem on centred, scaled data), shared.
// Cost:   O(N) plus a 4 x 4 eigen decomposition.
#ifndef PRIMITIVE_EDIT_FIT_SPHERE_DIRECT_H
#define PRIMITIVE_EDIT_FIT_SPHERE_DIRECT_H

#include "common/fit/fit_sphere.h"
#include "common/fit/quadric_direct_common.h"

namespace primitive_edit {

FitResult fit_sphere_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights = {});

} // namespace primitive_edit

#endif
