// fit_torus.h: torus through points.
//
// Input:  points N x 3 (N >= 8), normals N x 3 or empty, weights N or empty (= all 1), options.
// Output: FitResult with a Torus: origin = centre (on the axis, in the plane of the tube-centre circle),
//         unit axis (sign: largest component positive), radius = major radius R, minor_radius = tube
//         radius r. A failed status for bad input or when no start exists.
// Method: a torus is not a quadric, so it is started from the data: candidate axis lines, then the
//         meridian section (distance rho to the axis, height h along it) is fitted with a circle
//         (fit_circle_2d.h), whose centre is (R, height of the centre) and radius r; each start is
//         refined geometrically (refine_best_start.h), the best kept. Lines:
//         - from normals (given, or those of a Taubin quadric as a rough guess): every normal line of a
//           surface of revolution meets its axis; in Pluecker coordinates the axis (a, m) satisfies
//           (p x n) . a + n . m = 0 for every normal line (p, n) (Pottmann & Wallner), a 6 x 6
//           smallest-eigenvector problem on centred, scaled data;
//         - the directions of the cylinder-like starts (smallest eigenvector of sum n n^T, the
//           principal axes of the points), placed by a circle fit of the projected points.
//         Large inputs start on a 2000-point subsample; the winner is refined on all points.
// Cost:   O(N) per LM iteration.
#ifndef PRIMITIVE_EDIT_FIT_TORUS_H
#define PRIMITIVE_EDIT_FIT_TORUS_H

#include "common/base/canonicalize_primitive.h"
#include "common/geometry/axis_orthogonal_to_normals.h"
#include "common/fit/check_fit_input.h"
#include "common/fit/fit_circle_around_axis.h"
#include "common/fit/fit_start_normals.h"
#include "common/fit/minimum_points_for.h"
#include "common/fit/refine_best_start.h"
#include "common/geometry/weighted_pca.h"

#include <vector>

namespace primitive_edit {

namespace fit_torus_detail {

// The torus whose meridian circle best fits the points around the line (point c, unit direction a).
bool torus_around_line(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                       const Eigen::Vector3d& c, const Eigen::Vector3d& a, Primitive* out);

// The axis line met by all normal lines (see the header comment); false when it is not determined.
bool line_meeting_normals(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                          const Eigen::VectorXd& weights, Eigen::Vector3d* point, Eigen::Vector3d* axis);

} // namespace fit_torus_detail

FitResult fit_torus(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                    const Eigen::VectorXd& weights, const FitOptions& options = {});

} // namespace primitive_edit

#endif
