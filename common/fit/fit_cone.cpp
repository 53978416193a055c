#include "common/fit/fit_cone.h"

namespace primitive_edit {

namespace fit_cone_detail {

bool cone_around_line(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                      const Eigen::Vector3d& c, Eigen::Vector3d a, Primitive* out)
{
  double sw = 0, sh = 0, sr = 0, shh = 0, shr = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    const Eigen::Vector3d v = points.row(i).transpose() - c;
    const double h = v.dot(a), rho = (v - h * a).norm();
    sw += w, sh += w * h, sr += w * rho, shh += w * h * h, shr += w * h * rho;
  }
  if (!(sw > 0))
    return false;
  double mh = sh / sw;
  const double mr = sr / sw;
  const double var = shh / sw - mh * mh, cov = shr / sw - mh * mr;
  if (!(var > 0))
    return false;
  double k = cov / var;
  if (k < 0) {
    a = -a;
    mh = -mh;
    k = -k;
  }
  // Nearly cylindrical data: start from a small angle, the refinement finds the true one.
  k = std::max(k, 1e-3);
  out->type = PrimitiveType::Cone;
  out->axis = a;
  out->origin = c + (mh - mr / k) * a;
  out->half_angle = std::atan(k);
  return primitive_is_valid(*out);
}

bool line_from_cone_normals(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                            const Eigen::VectorXd& weights, Eigen::Vector3d* point, Eigen::Vector3d* axis)
{
  if (!normals.rows())
    return false;
  const WeightedPca spread = weighted_pca(normals, weights);
  if (!spread.ok || !(spread.eigenvalues[1] > 0))
    return false;
  *axis = spread.axes.col(0).normalized();
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d n = normals.row(i).transpose();
    const double w = weights.size() ? weights[i] : 1.0;
    A += w * n * n.transpose();
    b += w * n * n.dot(points.row(i).transpose());
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);
  if (!(eig.eigenvalues()[0] > 1e-6 * eig.eigenvalues()[2]))
    return false;
  *point = eig.eigenvectors() * (eig.eigenvalues().cwiseInverse().asDiagonal() * (eig.eigenvectors().transpose() * b));
  return point->allFinite() && axis->allFinite();
}

} // namespace fit_cone_detail

FitResult fit_cone(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                   const Eigen::VectorXd& weights, const FitOptions& options)
{
  FitResult out;
  out.status = check_fit_input(points, normals, weights, minimum_points_for(PrimitiveType::Cone));
  if (!out.status)
    return out;
  const FitSample s = fit_subsample(points, normals, weights, 2000);
  const Eigen::MatrixX3d start_normals = fit_start_normals(s);
  std::vector<Primitive> starts;
  Primitive p;
  Eigen::Vector3d c, a;
  if (fit_cone_detail::line_from_cone_normals(s.points, start_normals, s.weights, &c, &a) &&
      fit_cone_detail::cone_around_line(s.points, s.weights, c, a, &p))
    starts.push_back(p);
  std::vector<Eigen::Vector3d> directions;
  if (start_normals.rows()) {
    const WeightedPca by_normals = weighted_pca(start_normals, s.weights);
    if (by_normals.ok)
      directions.push_back(by_normals.axes.col(0).normalized());
    Eigen::Vector3d d;
    if (axis_orthogonal_to_normals(start_normals, s.weights, &d))
      directions.push_back(d);
  }
  const WeightedPca pca = weighted_pca(s.points, s.weights);
  for (int k = 2; k >= 0 && pca.ok; --k)
    directions.push_back(pca.axes.col(k).normalized());
  for (const Eigen::Vector3d& d : directions) {
    if (!d.allFinite())
      continue;
    const AxisCircle circle = fit_circle_around_axis(s.points, s.weights, d);
    if (circle.ok && fit_cone_detail::cone_around_line(s.points, s.weights, circle.centre, d, &p))
      starts.push_back(p);
  }
  return refine_best_start(starts, points, weights, s, options);
}

} // namespace primitive_edit
