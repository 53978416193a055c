#include "common/fit/fit_cone_direct.h"

namespace primitive_edit {

namespace fit_cone_direct_detail {

Eigen::Matrix<double, 9, 5> cone_basis(const Eigen::Vector3d& w)
{
  Eigen::Matrix<double, 9, 5> G;
  G.col(0) = quadric_direct::coefficients(w * w.transpose(), Eigen::Vector3d::Zero());
  G.col(1) = quadric_direct::coefficients(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  for (int j = 0; j < 3; ++j)
    G.col(2 + j) = quadric_direct::coefficients(Eigen::Matrix3d::Zero(), Eigen::Vector3d::Unit(j));
  return G;
}

} // namespace fit_cone_direct_detail

FitResult fit_cone_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  using namespace quadric_direct;
  FitResult out;
  const QuadricMoments m = checked_quadric_moments(PrimitiveType::Cone, points, weights, out.status);
  if (!out.status)
    return out;
  const Eigen::Vector3d w = minimise_over_axis<5>(m, fit_cone_direct_detail::cone_basis).normalized();
  Eigen::Matrix<double, 5, 1> theta = pencil_minimum<5>(m, fit_cone_direct_detail::cone_basis(w), true).theta;
  if (theta[0] < 0)
    theta = -theta;
  const double t = theta[0], k = t > 0 ? -theta[1] / t : -1.0;
  if (!(k > 0 && k < 1)) {
    out.status = Status::failure("the fitted quadric is no cone: its half angle is outside (0, 90) degrees "
                                 "(cylinder, sphere or plane data?)");
    return out;
  }
  // A = t (w w^T - k I) has eigenvalue t (1 - k) along w and -t k across it.
  const Eigen::Matrix3d along = w * w.transpose();
  const Eigen::Matrix3d A_inverse = (along / (1 - k) - (Eigen::Matrix3d::Identity() - along) / k) / t;
  Primitive p;
  p.type = PrimitiveType::Cone;
  p.origin = m.centroid - m.scale * A_inverse * theta.tail<3>() / 2;
  p.axis = (m.centroid - p.origin).dot(w) >= 0 ? w : Eigen::Vector3d(-w);
  p.half_angle = std::acos(std::sqrt(k));
  // Near-cylinder data give k ~ 1 - 1e-16, where the apex height b . w / (1 - k) is round-off; the
  // points' mean distance from the axis over tan(half angle) is where a cone through them puts its apex.
  double distance = 0, sum_w = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double wi = weights.size() ? weights[i] : 1.0;
    const Eigen::Vector3d v = points.row(i).transpose() - p.origin;
    distance += wi * (v - v.dot(w) * w).norm();
    sum_w += wi;
  }
  const double apex_height = distance / sum_w / std::tan(p.half_angle);
  const double extent = data_extent(points);
  if (!(apex_height <= 1e4 * extent) || (p.origin - m.centroid).norm() > 1e4 * extent) {
    out.status = Status::failure("the cone's apex is farther than 1e4 times the data extent (cylinder data?)");
    return out;
  }
  return direct_fit_result(p, points, weights);
}

} // namespace primitive_edit
