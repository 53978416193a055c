// fit_cone_direct.h: the paper's direct (algebraic, type-constrained) cone fit, without refinement.
//
// Input:  points N x 3 (N >= 7), weights N or empty (= all 1). No normals: the fit does not need them.
// Output: FitResult with a Cone: origin = apex, unit axis from the apex into the opening (towards the
//         points' weighted centroid), half angle in (0, pi/2); rms / max_residual / point_count of the
//         orthogonal distances of all points of positive weight. A failed status for bad input
//         (check_fit_input.h), collinear or coplanar points, a quadric whose half angle is outside
//         (0, 90) degrees (e.g. cylinder or sphere data) and an apex farther than 1e4 times the data's
//         extent from the points.
// Method: Andrews & Sequin's cone type: ((x - v) . w)^2 - cos^2(angle) |x - v|^2 = 0, i.e. the quadric
//         x^T A x + b . x + c with A = t (w w^T - k I), k = cos^2(angle), b = -2 A v. For a fixed axis w,
//         A = t w w^T + sigma I is linear in (t, sigma), and with b free the coefficients
//         (t, sigma, b, c) enter linearly: a 5 x 5 generalised eigenproblem (c eliminated;
//         quadric_direct_common.h) whose smallest eigenvalue is minimised over w on the sphere of
//         directions (grid, compass search, Newton; quadric_direct_common.h). The apex condition
//         c = v^T A v (a cone, not a hyperboloid of revolution) is left out of the solve to keep it
//         linear; exact cone data satisfy it, noisy data give the hyperboloid's centre as the apex.
//         Read-off: k = -sigma / t, apex v = -A^{-1} b / 2, on the centred, scaled data, mapped back.
// Cost:   O(N) for the moments plus ~850 evaluations of a 5 x 5 generalised eigenproblem.
#ifndef PRIMITIVE_EDIT_FIT_CONE_DIRECT_H
#define PRIMITIVE_EDIT_FIT_CONE_DIRECT_H

#include "common/fit/quadric_direct_common.h"

namespace primitive_edit {

namespace fit_cone_direct_detail {

// The constraint for axis w: coefficients = G (t, sigma, b), A = t w w^T + sigma I (revolution about w).
Eigen::Matrix<double, 9, 5> cone_basis(const Eigen::Vector3d& w);

} // namespace fit_cone_direct_detail

FitResult fit_cone_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights = {});

} // namespace primitive_edit

#endif
