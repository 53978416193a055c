#include "common/fit/fit_cylinder_direct.h"

namespace primitive_edit {

namespace fit_cylinder_direct_detail {

Eigen::Matrix<double, 9, 3> cylinder_basis(const Eigen::Vector3d& w)
{
  const Eigen::Vector3d e1 = any_orthogonal(w), e2 = w.cross(e1);
  Eigen::Matrix<double, 9, 3> G;
  G.col(0) = quadric_direct::coefficients(Eigen::Matrix3d::Identity() - w * w.transpose(), Eigen::Vector3d::Zero());
  G.col(1) = quadric_direct::coefficients(Eigen::Matrix3d::Zero(), e1);
  G.col(2) = quadric_direct::coefficients(Eigen::Matrix3d::Zero(), e2);
  return G;
}

} // namespace fit_cylinder_direct_detail

FitResult fit_cylinder_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  using namespace quadric_direct;
  FitResult out;
  const QuadricMoments m = checked_quadric_moments(PrimitiveType::Cylinder, points, weights, out.status);
  if (!out.status)
    return out;
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
  p.axis = largest_component_positive(p.axis);
  return direct_fit_result(p, points, weights);
}

} // namespace primitive_edit
