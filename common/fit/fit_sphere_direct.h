// fit_sphere_direct.h: the paper's direct (algebraic, type-constrained) sphere fit, without refinement.
//
// Input:  points N x 3 (N >= 4), weights N or empty (= all 1).
// Output: FitResult with a Sphere (origin = centre, radius); rms / max_residual / point_count of the
//         orthogonal distances of all points of positive weight. A failed status for bad input
//         (check_fit_input.h), collinear or coplanar points, and a radius above 1e4 times the data's
//         extent (nearly planar points).
// Method: Andrews & Sequin's sphere type: A = a I, i.e. f = a |x|^2 + b . x + c, with Taubin's
//         (= Pratt's, for spheres) normalisation: the same solve as fit_sphere's first start
//         (fit_sphere_detail::taubin_sphere, a 4 x 4 eigenproblem on centred, scaled data), shared.
// Cost:   O(N) plus a 4 x 4 eigen decomposition.
#ifndef PRIMITIVE_EDIT_FIT_SPHERE_DIRECT_H
#define PRIMITIVE_EDIT_FIT_SPHERE_DIRECT_H

#include "common/fit/fit_sphere.h"
#include "common/fit/quadric_direct_common.h"

namespace primitive_edit {

inline FitResult fit_sphere_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights = {})
{
  FitResult out;
  out.status = quadric_direct::check_direct_input(PrimitiveType::Sphere, points, weights);
  if (!out.status)
    return out;
  Primitive p;
  if (!fit_sphere_detail::taubin_sphere(points, weights, &p)) {
    out.status = Status::failure("the points determine no sphere (the algebraic fit is a plane)");
    return out;
  }
  const double extent = quadric_direct::data_extent(points);
  if (p.radius > 1e4 * extent) {
    out.status = Status::failure("points are (nearly) coplanar: sphere radius " + std::to_string(p.radius) +
                                 " exceeds 1e4 times the data extent");
    return out;
  }
  return quadric_direct::direct_fit_result(p, points, weights);
}

} // namespace primitive_edit

#endif
