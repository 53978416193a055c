#include "common/geometry/fit_circle_2d.h"

namespace primitive_edit {

Circle2d fit_circle_2d(const Eigen::MatrixX2d& points, const Eigen::VectorXd& weights)
{
  Circle2d out;
  const Eigen::Index n = points.rows();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  double sum_w = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    mean += w * points.row(i).transpose();
    sum_w += w;
  }
  if (!(sum_w > 0))
    return out;
  mean /= sum_w;
  double z_mean = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    z_mean += w * (points.row(i).transpose() - mean).squaredNorm();
  }
  z_mean /= sum_w;
  if (!(z_mean > 0))
    return out;
  const double s = 2 * std::sqrt(z_mean);
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    const Eigen::Vector2d q = points.row(i).transpose() - mean;
    const Eigen::Vector3d row((q.squaredNorm() - z_mean) / s, q.x(), q.y());
    M += w * row * row.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(M);
  Eigen::Vector3d A = eig.eigenvectors().col(0);
  const double a0 = A[0] / s;
  const double a3 = -z_mean * a0;
  // |a0| relative to the linear terms says how far from a line the points are.
  if (!(std::abs(a0) * std::sqrt(z_mean) > 1e-9 * A.tail<2>().norm()))
    return out;
  out.centre = mean - A.tail<2>() / (2 * a0);
  const double r2 = A.tail<2>().squaredNorm() - 4 * a0 * a3;
  if (!(r2 > 0))
    return out;
  out.radius = std::sqrt(r2) / (2 * std::abs(a0));
  out.ok = out.centre.allFinite() && std::isfinite(out.radius) && out.radius > 0;
  return out;
}

} // namespace primitive_edit
