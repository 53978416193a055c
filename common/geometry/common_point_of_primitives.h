// common_point_of_primitives.h: the point nearest to p lying on three or more primitives (the sharp
// corner where snapped segments meet); for three planes this is their exact corner.
//
// Input:  k >= 3 valid primitives (pointers, none null), a point p, and max_distance: how far from p
//         the answer may lie.
// Output: true and `result` on every surface (to ~1e-10 of the coordinates' size). False, with
//         `result` untouched, when fewer than 3 primitives are given (use
//         closest_point_on_intersection for two), an input is invalid or non-finite, the surfaces do not
//         meet in one isolated point near p (their normals there do not span space: smallest singular
//         value of the k x 3 normal matrix below sin 5 degrees, e.g. three planes through one line),
//         the surfaces miss each other (least-squares residual not ~0, e.g. four planes that are not
//         concurrent), the point is farther than max_distance from p, or no convergence.
// Method: Gauss-Newton on the signed distances f_i(x) = 0 with the unit normals as Jacobian rows: each
//         step solves the linearised system in the least-squares sense for the point nearest p,
//         x <- p - J^+ (f(x) + J (p - x)), J^+ the pseudo-inverse (rank-truncated, so the iteration
//         stays defined where normals align). For three independent surfaces this is Newton's method.
// Cost:   O(k) per iteration, at most 100 iterations.
#ifndef PRIMITIVE_EDIT_COMMON_POINT_OF_PRIMITIVES_H
#define PRIMITIVE_EDIT_COMMON_POINT_OF_PRIMITIVES_H

#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/iterate_to_nearest_solution.h"
#include "common/base/primitive.h"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace primitive_edit {

bool common_point_of_primitives(const std::vector<const Primitive*>& primitives, const Eigen::Vector3d& p,
                                double max_distance, Eigen::Vector3d& result);

} // namespace primitive_edit

#endif
