// fit_sphere.h: sphere through points.
//
// Input:  points N x 3 (N >= 4), normals N x 3 or empty, weights N or empty (= all 1), options.
// Output: FitResult with a Sphere (origin = centre, radius). A failed status for bad input and for
//         (nearly) coplanar or collinear points: no start exists, or the sphere's radius exceeds
//         1e4 times the data's extent (a plane, not a sphere).
// Method: two starts, each refined geometrically (refine_best_start.h):
//         1. the type-constrained algebraic fit of Andrews & Sequin for the sphere type, i.e. the
//            quadric x^2+y^2+z^2 + b.x + c with Taubin's (= Pratt's, for spheres) gradient
//            normalisation, solved as a 4 x 4 eigenproblem on centred, scaled data (Chernov's
//            TaubinSVD in 3D); nearly unbiased on caps, unlike the Kasa fit;
//         2. with normals: the point nearest to all normal lines p + t n (3 x 3 linear system),
//            radius = mean distance to it.
//         Large inputs start on a 2000-point subsample; the winner is refined on all points.
// Cost:   O(N) per LM iteration.
#ifndef PRIMITIVE_EDIT_FIT_SPHERE_H
#define PRIMITIVE_EDIT_FIT_SPHERE_H

#include "common/fit/check_fit_input.h"
#include "common/fit/fit_subsample.h"
#include "common/fit/minimum_points_for.h"
#include "common/fit/refine_best_start.h"

#include <Eigen/Eigenvalues>

#include <vector>

namespace primitive_edit {

namespace fit_sphere_detail {

bool taubin_sphere(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, Primitive* out);

bool normal_lines_sphere(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                         const Eigen::VectorXd& weights, Primitive* out);

} // namespace fit_sphere_detail

FitResult fit_sphere(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                     const Eigen::VectorXd& weights, const FitOptions& options = {});

} // namespace primitive_edit

#endif
