// fit_cylinder_direct.h: the paper's direct (algebraic, type-constrained) cylinder fit, without refinement.
//
// Input:  points N x 3 (N >= 6), weights N or empty (= all 1). No normals: the fit does not need them.
// Output: FitResult with a Cylinder: origin = the axis point closest to the weighted centroid, unit axis
//         (largest component positive), radius; rms / max_residual / point_count of the orthogonal
//         distances of all points of positive weight. A failed status for bad input (check_fit_input.h),
//         collinear or coplanar points, a quadric that is no real cylinder, and a radius above 1e4 times
//         the data's extent (nearly planar points).
// Method: Andrews & Sequin's cylinder type: the quadric x^T A x + b . x + c with A rank 2, positive
//         semi-definite, equal non-zero eigenvalues: A = s (I - w w^T) for the unit axis w, and b
//         orthogonal to w (otherwise it is a paraboloid). For a fixed w the coefficients (s, b in the
//         plane orthogonal to w, c) enter linearly, so the Taubin-normalised algebraic cost is a 3 x 3
//         generalised eigenproblem (c eliminated; quadric_direct_common.h) = a Taubin circle fit of the
//         points projected along w. Its smallest eigenvalue is minimised over w on the sphere of
//         directions (grid, compass search, Newton; quadric_direct_common.h). Read-off: centre
//         -b / (2 s), radius^2 = |b|^2 / (4 s^2) - c / s, on the centred, scaled data, then mapped back.
// Cost:   O(N) for the moments plus ~850 evaluations of a 3 x 3 generalised eigenproblem.
#ifndef PRIMITIVE_EDIT_FIT_CYLINDER_DIRECT_H
#define PRIMITIVE_EDIT_FIT_CYLINDER_DIRECT_H

#include "common/fit/quadric_direct_common.h"

namespace primitive_edit {

namespace fit_cylinder_direct_detail {

// The cylinder constraint for axis w: coefficients = G (s, b1, b2), b = b1 e1 + b2 e2 orthogonal to w.
inline Eigen::Matrix<double, 9, 3> cylinder_basis(const Eigen::Vector3d& w)
{
  const Eigen::Vector3d e1 = any_orthogonal(w), e2 = w.cross(e1);
  Eigen::Matrix<double, 9, 3> G;
  G.col(0) = quadric_direct::coefficients(Eigen::Matrix3d::Identity() - w * w.transpose(), Eigen::Vector3d::Zero());
  G.col(1) = quadric_direct::coefficients(Eigen::Matrix3d::Zero(), e1);
  G.col(2) = quadric_direct::coefficients(Eigen::Matrix3d::Zero(), e2);
  return G;
}

} // namespace fit_cylinder_direct_detail

inline FitResult fit_cylinder_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights = {})
{
  using namespace quadric_direct;
  FitResult out;
  out.status = check_direct_input(PrimitiveType::Cylinder, points, weights);
  if (!out.status)
    return out;
  const QuadricMoments m = quadric_moments(points, weights);
  if (!m.ok) {
    out.status = Status::failure("the points' quadric moments are not finite");
    return out;
  }
  const Eigen::Vector3d w = minimise_over_axis<3>(m, fit_cylinder_direct_detail::cylinder_basis);
  const Eigen::Matrix<double, 9, 3> G = fit_cylinder_direct_detail::cylinder_basis(w);
  const PencilMinimum<3> best = pencil_minimum<3>(m, G, true);
  const Vec9 c = G * best.theta;
  const double s = best.theta[0], c0 = -c.dot(m.mean);
  const Eigen::Vector3d b = c.tail<3>();
  // s -> 0 is a plane; |b| is O(1) on the scaled data, so this bounds the radius at ~1e9 data sizes.
  const double r2 = std::abs(s) > 1e-9 * b.norm() ? b.squaredNorm() / (4 * s * s) - c0 / s : -1.0;
  if (!(r2 > 0)) {
    out.status = Status::failure("the fitted quadric is no real cylinder (points nearly planar?)");
    return out;
  }
  Primitive p;
  p.type = PrimitiveType::Cylinder;
  p.axis = w.normalized();
  p.origin = m.centroid - m.scale * b / (2 * s);
  p.radius = m.scale * std::sqrt(r2);
  if (p.radius > 1e4 * data_extent(points)) {
    out.status = Status::failure("points are (nearly) planar: cylinder radius " + std::to_string(p.radius) +
                                 " exceeds 1e4 times the data extent");
    return out;
  }
  Eigen::Index k = 0;
  p.axis.cwiseAbs().maxCoeff(&k);
  if (p.axis[k] < 0)
    p.axis = -p.axis;
  return direct_fit_result(p, points, weights);
}

} // namespace primitive_edit

#endif
