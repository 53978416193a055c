#include "common/fit/fit_cylinder.h"

namespace primitive_edit {

FitResult fit_cylinder(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                       const Eigen::VectorXd& weights, const FitOptions& options)
{
  FitResult out;
  out.status = check_fit_input(points, normals, weights, minimum_points_for(PrimitiveType::Cylinder));
  if (!out.status)
    return out;
  const FitSample s = fit_subsample(points, normals, weights, 2000);
  std::vector<Eigen::Vector3d> directions;
  Eigen::Vector3d a;
  if (axis_orthogonal_to_normals(fit_start_normals(s), s.weights, &a))
    directions.push_back(a);
  const WeightedPca pca = weighted_pca(s.points, s.weights);
  for (int k = 2; k >= 0 && pca.ok; --k)
    directions.push_back(pca.axes.col(k).normalized());
  std::vector<Primitive> starts;
  for (const Eigen::Vector3d& d : directions) {
    const AxisCircle c = fit_circle_around_axis(s.points, s.weights, d);
    if (!c.ok)
      continue;
    Primitive p;
    p.type = PrimitiveType::Cylinder;
    p.origin = c.centre;
    p.axis = d;
    p.radius = c.radius;
    starts.push_back(p);
  }
  out = refine_best_start(starts, points, weights, s, options);
  if (out.status.ok())
    out.primitive.axis = largest_component_positive(out.primitive.axis);
  return out;
}

} // namespace primitive_edit
