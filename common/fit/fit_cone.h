// fit_cone.h: circular cone (one nappe) through points.
//
// Input:  points N x 3 (N >= 7), normals N x 3 or empty, weights N or empty (= all 1), options.
// Output: FitResult with a Cone: origin = apex, unit axis from the apex into the opening (towards
//         the points), half angle in (0, pi/2). Data of a cylinder give a cone with a tiny half angle
//         and a far apex (fit_primitive_auto then prefers the cylinder). A failed status for bad input or
//         when no start exists.
// Method: candidate axis lines, each turned into a cone by regressing the distance to the line on
//         the height along it (rho = rho0 + h tan(alpha): the cone's generator), refined
//         geometrically (refine_best_start.h), best kept. Lines:
//         - from normals (given, or those of the Taubin quadric Andrews & Sequin start from, exact on
//           exact cone data): a cone's normals make a constant angle with the axis, so the axis
//           minimises sum w (n . a - mean)^2 = smallest eigenvector of the normals' covariance; the
//           apex lies on every tangent plane: least squares of n_i . (x - p_i) = 0 (3 x 3 system);
//         - the cylinder-style directions (smallest eigenvector of sum n n^T, principal axes of the
//           points), placed by a circle fit of the projected points (fit_circle_around_axis.h).
//         Large inputs start on a 2000-point subsample; the winner is refined on all points.
// Cost:   O(N) per LM iteration.
#ifndef PRIMITIVE_EDIT_FIT_CONE_H
#define PRIMITIVE_EDIT_FIT_CONE_H

#include "common/geometry/axis_orthogonal_to_normals.h"
#include "common/fit/check_fit_input.h"
#include "common/fit/fit_circle_around_axis.h"
#include "common/fit/fit_start_normals.h"
#include "common/fit/minimum_points_for.h"
#include "common/fit/refine_best_start.h"
#include "common/geometry/weighted_pca.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace primitive_edit {

namespace fit_cone_detail {

// The cone whose generator best matches rho(h) around the line (point c, unit direction a).
bool cone_around_line(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                      const Eigen::Vector3d& c, Eigen::Vector3d a, Primitive* out);

// Axis line of a cone from its normals (see the header comment); false when they do not determine it.
bool line_from_cone_normals(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                            const Eigen::VectorXd& weights, Eigen::Vector3d* point, Eigen::Vector3d* axis);

} // namespace fit_cone_detail

FitResult fit_cone(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                   const Eigen::VectorXd& weights, const FitOptions& options = {});

} // namespace primitive_edit

#endif
