// check_fit_input.h: validation of the arrays given to a primitive fit.
//
// Input:  points N x 3, normals (N x 3 or empty), weights (N or empty = all 1), the minimum number
//         of points the fit needs.
// Output: success when the input is usable; otherwise a failure saying why. Non-finite
//         coordinates, normals or weights are rejected (not dropped): a mesh with NaN vertices is
//         broken and silently ignoring part of it would hide that. Negative weights, mismatched
//         sizes and fewer than min_points points of positive weight are rejected too.
// Cost:   O(N).
#ifndef PRIMITIVE_EDIT_CHECK_FIT_INPUT_H
#define PRIMITIVE_EDIT_CHECK_FIT_INPUT_H

#include "common/base/status.h"

#include <Eigen/Core>

#include <string>

namespace primitive_edit {

Status check_fit_input(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                       const Eigen::VectorXd& weights, int min_points);

} // namespace primitive_edit

#endif
