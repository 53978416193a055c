#include "common/fit/fit_torus.h"

namespace primitive_edit {

namespace fit_torus_detail {

bool torus_around_line(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                       const Eigen::Vector3d& c, const Eigen::Vector3d& a, Primitive* out)
{
  Eigen::MatrixX2d section(points.rows(), 2);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d v = points.row(i).transpose() - c;
    const double h = v.dot(a);
    section(i, 0) = (v - h * a).norm();
    section(i, 1) = h;
  }
  const Circle2d m = fit_circle_2d(section, weights);
  if (!m.ok)
    return false;
  out->type = PrimitiveType::Torus;
  out->axis = a;
  out->origin = c + m.centre.y() * a;
  out->radius = m.centre.x();
  out->minor_radius = m.radius;
  return primitive_is_valid(*out);
}

bool line_meeting_normals(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                          const Eigen::VectorXd& weights, Eigen::Vector3d* point, Eigen::Vector3d* axis)
{
  if (!normals.rows())
    return false;
  const WeightedPca pca = weighted_pca(points, weights);
  const double scale = std::sqrt(pca.eigenvalues.sum());
  if (!pca.ok || !(scale > 0))
    return false;
  using Vec6 = Eigen::Matrix<double, 6, 1>;
  using Mat6 = Eigen::Matrix<double, 6, 6>;
  Mat6 M = Mat6::Zero();
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d p = (points.row(i).transpose() - pca.centroid) / scale;
    const Eigen::Vector3d n = normals.row(i).transpose();
    Vec6 row;
    row << p.cross(n), n;
    M.selfadjointView<Eigen::Lower>().rankUpdate(row, weights.size() ? weights[i] : 1.0);
  }
  M = M.selfadjointView<Eigen::Lower>();
  Eigen::SelfAdjointEigenSolver<Mat6> eig(M);
  const Vec6 x = eig.eigenvectors().col(0);
  const double len = x.head<3>().norm();
  if (!(len > 1e-6))
    return false;
  const Eigen::Vector3d a = x.head<3>() / len, m = x.tail<3>() / len;
  *axis = a;
  *point = pca.centroid + scale * a.cross(m);
  return point->allFinite() && axis->allFinite();
}

} // namespace fit_torus_detail

FitResult fit_torus(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                    const Eigen::VectorXd& weights, const FitOptions& options)
{
  FitResult out;
  out.status = check_fit_input(points, normals, weights, minimum_points_for(PrimitiveType::Torus));
  if (!out.status)
    return out;
  const FitSample s = fit_subsample(points, normals, weights, 2000);
  const Eigen::MatrixX3d start_normals = fit_start_normals(s);
  std::vector<Primitive> starts;
  Primitive p;
  Eigen::Vector3d c, a;
  if (fit_torus_detail::line_meeting_normals(s.points, start_normals, s.weights, &c, &a) &&
      fit_torus_detail::torus_around_line(s.points, s.weights, c, a, &p))
    starts.push_back(p);
  std::vector<Eigen::Vector3d> directions;
  if (axis_orthogonal_to_normals(start_normals, s.weights, &a))
    directions.push_back(a);
  const WeightedPca pca = weighted_pca(s.points, s.weights);
  for (int k = 0; k < 3 && pca.ok; ++k)
    directions.push_back(pca.axes.col(k).normalized());
  for (const Eigen::Vector3d& d : directions) {
    const AxisCircle circle = fit_circle_around_axis(s.points, s.weights, d);
    if (circle.ok && fit_torus_detail::torus_around_line(s.points, s.weights, circle.centre, d, &p))
      starts.push_back(p);
  }
  out = refine_best_start(starts, points, weights, s, options);
  if (out.status.ok())
    out.primitive.axis = largest_component_positive(out.primitive.axis);
  return out;
}

} // namespace primitive_edit
