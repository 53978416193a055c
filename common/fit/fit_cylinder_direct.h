// fit_cylinder_direct.h: the paper's direct (algebraic, type-constrained) cylinder fit, without refinement.
//
// Input:  points N x 3 (N >= 6), weights N or empty (= all 1). No normals: the fit does not need them.
// Output: FitResult with a Cylinder: origin = the axis point closest to the weighted centroid, unit axis
//         (largest component positive), radius; rms / max_residual / point_count of the orthogonal
//         distances of all points of positive weight. A failed status for bad input (check_fit_input.h),
//         collinear or coplanar points, a quadric that is no real cylinder, and a radius above 1e4 times
//         the data's extent (nearly planar points).
// Method: Andrews & Sequin's cylinder type: the quadric x^T A x + b . x + c with A rank 2, positive
//         semi-definite, equal non-zero eigenvalues: A = s (I - w w^T) for the unit axis w, and b
//         orthogonal to w (otherwise it is a paraboloid). For a fixed w the coefficients (s, b in the
//         plane orthogonal to w, c) enter linearly, so the Taubin-normalised algebraic cost is a 3 x 3
//         generalised eigenproblem (c eliminated; quadric_direct_common.h) = a Taubin circle fit of the
//         points projected along w. Its smallest eigenvalue is minimised over w on the sphere of
//         directions (grid, compass search, Newton; quadric_direct_common.h). Read-off: centre
//         -b / (2 s), radius^2 = |b|^2 / (4 s^2) - c / s, on the centred, scaled data, then mapped back.
// Cost:   O(N) for the moments plus ~850 evaluations of a 3 x 3 generalised eigenproblem.
#ifndef PRIMITIVE_EDIT_FIT_CYLINDER_DIRECT_H
#define PRIMITIVE_EDIT_FIT_CYLINDER_DIRECT_H

#include "common/fit/quadric_direct_common.h"

namespace primitive_edit {

namespace fit_cylinder_direct_detail {

// The cylinder constraint for axis w: coefficients = G (s, b1, b2), b = b1 e1 + b2 e2 orthogonal to w.
Eigen::Matrix<double, 9, 3> cylinder_basis(const Eigen::Vector3d& w);

} // namespace fit_cylinder_direct_detail

FitResult fit_cylinder_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights = {});

} // namespace primitive_edit

#endif
