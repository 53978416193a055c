#include "common/fit/fit_sphere.h"

namespace primitive_edit {

namespace fit_sphere_detail {

bool taubin_sphere(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, Primitive* out)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double sum_w = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    mean += w * points.row(i).transpose();
    sum_w += w;
  }
  if (!(sum_w > 0))
    return false;
  mean /= sum_w;
  double z_mean = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    z_mean += (weights.size() ? weights[i] : 1.0) * (points.row(i).transpose() - mean).squaredNorm();
  z_mean /= sum_w;
  if (!(z_mean > 0))
    return false;
  const double s = 2 * std::sqrt(z_mean);
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d q = points.row(i).transpose() - mean;
    const Eigen::Vector4d row((q.squaredNorm() - z_mean) / s, q.x(), q.y(), q.z());
    M += (weights.size() ? weights[i] : 1.0) * row * row.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(M);
  const Eigen::Vector4d A = eig.eigenvectors().col(0);
  const double a0 = A[0] / s;
  if (!(std::abs(a0) * std::sqrt(z_mean) > 1e-9 * A.tail<3>().norm()))
    return false;
  const double r2 = A.tail<3>().squaredNorm() + 4 * a0 * a0 * z_mean;
  out->type = PrimitiveType::Sphere;
  out->origin = mean - A.tail<3>() / (2 * a0);
  out->radius = std::sqrt(r2) / (2 * std::abs(a0));
  return primitive_is_valid(*out);
}

bool normal_lines_sphere(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                         const Eigen::VectorXd& weights, Primitive* out)
{
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d n = normals.row(i).transpose();
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - n * n.transpose();
    const double w = weights.size() ? weights[i] : 1.0;
    A += w * P;
    b += w * P * points.row(i).transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);
  if (!(eig.eigenvalues()[0] > 1e-6 * eig.eigenvalues()[2]))
    return false;
  const Eigen::Vector3d c = eig.eigenvectors() * (eig.eigenvalues().cwiseInverse().asDiagonal() *
                                                  (eig.eigenvectors().transpose() * b));
  double r = 0, sum_w = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    r += w * (points.row(i).transpose() - c).norm();
    sum_w += w;
  }
  out->type = PrimitiveType::Sphere;
  out->origin = c;
  out->radius = r / sum_w;
  return primitive_is_valid(*out);
}

} // namespace fit_sphere_detail

FitResult fit_sphere(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                     const Eigen::VectorXd& weights, const FitOptions& options)
{
  FitResult out;
  out.status = check_fit_input(points, normals, weights, minimum_points_for(PrimitiveType::Sphere));
  if (!out.status)
    return out;
  const FitSample s = fit_subsample(points, normals, weights, 2000);
  std::vector<Primitive> starts;
  Primitive p;
  if (fit_sphere_detail::taubin_sphere(s.points, s.weights, &p))
    starts.push_back(p);
  if (s.normals.rows() && fit_sphere_detail::normal_lines_sphere(s.points, s.normals, s.weights, &p))
    starts.push_back(p);
  if (starts.empty()) {
    out.status = Status::failure("points are coplanar or collinear: no sphere");
    return out;
  }
  out = refine_best_start(starts, points, weights, s, options);
  const double extent = (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  if (out.status.ok() && out.primitive.radius > 1e4 * extent) {
    out.status = Status::failure("points are (nearly) coplanar: sphere radius " + std::to_string(out.primitive.radius) +
                                 " exceeds 1e4 times the data extent");
  }
  return out;
}

} // namespace primitive_edit
