// refine_primitive.h: geometric (orthogonal-distance) refinement of a primitive, shared by all fits.
//
// Input:  a start primitive (valid), points N x 3, weights N (non-negative, empty = all 1), options,
//         the number of reweighting rounds (fewer than 6: the start is already a robust fit of a
//         subsample, so only the tight rounds are run).
// Output: a FitResult: the primitive minimising sum w_i d_i^2, d_i the signed orthogonal distance
//         (closest_point_on_primitive.h), by Levenberg-Marquardt; with options.robust, iteratively
//         reweighted with Tukey's biweight (c = 4.685 * 1.4826 * median |d|, first rounds wider) so
//         that outliers (e.g. points of a neighbouring surface at the segment border) get weight 0.
//         rms / max_residual / point_count are over the points of final weight > 0, in the output
//         conventions of canonicalize_primitive.h. A failed status if the start is invalid, the points or
//         weights are not usable (check_fit_input.h: non-finite, negative weights, no point of positive
//         weight) or the refinement could not keep a valid primitive.
// Method: the parameters are local to the current primitive and re-based after every accepted step:
//         axis a -> normalize(a + t1 e1 + t2 e2) with e1, e2 orthogonal to a, so no parametrisation
//         singularity. Unknowns: plane (offset, t1, t2), sphere (centre, r), cylinder (2 shifts of the
//         axis orthogonal to itself, t1, t2, r), cone (apex, t1, t2, half angle), torus (centre, t1, t2,
//         R, r). Jacobians are analytic. A step that would leave the valid domain (radius <= 0, half
//         angle outside (0, pi/2)) is rejected like a step that increases the cost.
// Cost:   O(N) per tried step (cost and J^T J in one pass), at most max_iterations
//         iterations per reweighting round, at most 6 rounds (until the inlier set is stable).
#ifndef PRIMITIVE_EDIT_REFINE_PRIMITIVE_H
#define PRIMITIVE_EDIT_REFINE_PRIMITIVE_H

#include "common/base/canonicalize_primitive.h"
#include "common/fit/check_fit_input.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/fit/fit_residuals.h"
#include "common/fit/fit_result.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace primitive_edit {

namespace refine_detail {

using Vec7 = Eigen::Matrix<double, 7, 1>;
using Mat7 = Eigen::Matrix<double, 7, 7>;

// What residual() needs of a primitive besides its parameters, computed once per pass over the points:
// the basis e1, e2 orthogonal to the axis that the local parameters turn it along, and the cone's
// cos/sin of the half angle.
struct LocalFrame
{
  Eigen::Vector3d e1, e2;
  double cos_angle = 1, sin_angle = 0;
};

LocalFrame local_frame(const Primitive& p);

// Signed distance of x to p and, if J is given, its gradient with respect to the local parameters at 0.
double residual(const Primitive& p, const LocalFrame& frame, const Eigen::Vector3d& x, Vec7* J);

// The primitive at local parameters d; false if it leaves the valid domain.
bool apply_step(const Primitive& p, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, const Vec7& d,
                Primitive* out);

// Cost sum w r^2 and the normal equations J^T W J, J^T W r at p, in one pass. Only the leading block of the type's
// primitive_degrees_of_freedom parameters can be non-zero (the Jacobian's other entries are 0), and only it is
// accumulated.
double normal_equations(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w,
                        Mat7* JtJ, Vec7* Jtr);

// Levenberg-Marquardt with Marquardt's diagonal scaling on sum w_i d_i^2. Each tried step costs one
// pass (cost and normal equations together). Stops when the RMS falls below `exact_rms` (round-off
// level: exact data) or the cost stalls.
Primitive levenberg_marquardt(Primitive p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w,
                              int max_iterations, double exact_rms);

double median_abs(std::vector<double> v);

// Tukey biweight weights (times the input weights) for the residuals of p; `wide` widens c in early rounds.
Eigen::VectorXd tukey_weights(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w,
                              double wide, double floor);

} // namespace refine_detail

FitResult refine_primitive(const Primitive& start, const Eigen::MatrixX3d& points,
                           const Eigen::VectorXd& weights, const FitOptions& options = {},
                           int max_rounds = 6);

} // namespace primitive_edit

#endif
