// fit_residuals.h: the RMS and maximum orthogonal distance of points to a primitive.
//
// Input:  a primitive, points N x 3, weights N (empty = all 1). Points of zero weight are ignored.
// Output: a FitResult with the primitive, rms = sqrt(sum w d^2 / sum w) (weights as given, e.g. areas),
//         max_residual = max |d|, point_count = number of points with w > 0, and ok = the primitive is
//         valid and at least one point counted.
// Cost:   O(N).
#ifndef PRIMITIVE_EDIT_FIT_RESIDUALS_H
#define PRIMITIVE_EDIT_FIT_RESIDUALS_H

#include "common/geometry/closest_point_on_primitive.h"
#include "common/fit/fit_result.h"

#include <algorithm>
#include <cmath>

namespace primitive_edit {

FitResult fit_residuals(const Primitive& prim, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights);

} // namespace primitive_edit

#endif
