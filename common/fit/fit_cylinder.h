// fit_cylinder.h: circular cylinder through points.
//
// Input:  points N x 3 (N >= 6), normals N x 3 or empty, weights N or empty (= all 1), options.
// Output: FitResult with a Cylinder: origin = the axis point closest to the (inlier) centroid, unit
//         axis (sign: largest component positive), radius. A failed status for bad input or when no
//         start exists (e.g. collinear points).
// Method: candidate axis directions, each placed by a circle fit of the points projected along it
//         (fit_circle_around_axis.h), refined geometrically (refine_best_start.h), best kept:
//         - from normals: the direction minimising sum w (n . a)^2 = smallest eigenvector of
//           sum w n n^T (cylinder normals are orthogonal to the axis). Without given normals, the
//           normals of the Taubin quadric (the algebraic fit Andrews & Sequin constrain; exact on
//           exact cylinder data) are used instead;
//         - the three principal axes of the points (long cylinders, fallback without normals).
//         A direction along which the points are seen as a line (flat data) starts a cylinder of radius 1e6
//         times their spread (standard deviation along their longest axis) lying on their plane: the
//         degenerate best cylinder, which callers then find implausibly large, rather than only the starts
//         about other directions.
//         A direct type-constrained quadric solve was not used: on a short arc of noisy data it is
//         biased anyway, and the normal-based axis plus the geometric refinement is more robust.
//         Large inputs start on a 2000-point subsample; the winner is refined on all points.
// Cost:   O(N) per LM iteration.
#ifndef PRIMITIVE_EDIT_FIT_CYLINDER_H
#define PRIMITIVE_EDIT_FIT_CYLINDER_H

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

FitResult fit_cylinder(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                       const Eigen::VectorXd& weights, const FitOptions& options = {});

} // namespace primitive_edit

#endif
