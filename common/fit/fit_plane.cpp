#include "common/fit/fit_plane.h"

namespace primitive_edit {

FitResult fit_plane(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                    const Eigen::VectorXd& weights, const FitOptions& options)
{
  FitResult out;
  out.status = check_fit_input(points, normals, weights, minimum_points_for(PrimitiveType::Plane));
  if (!out.status)
    return out;
  const WeightedPca pca = weighted_pca(points, weights);
  if (!pca.ok || !(pca.eigenvalues[1] > 1e-12 * pca.eigenvalues[2])) {
    out.status = Status::failure("points are collinear or coincident: no unique plane");
    return out;
  }
  Primitive start;
  start.type = PrimitiveType::Plane;
  start.origin = pca.centroid;
  start.axis = pca.axes.col(0).normalized();
  if (normals.rows()) {
    double orientation = 0;
    for (Eigen::Index i = 0; i < normals.rows(); ++i)
      orientation += (weights.size() ? weights[i] : 1.0) * normals.row(i).dot(start.axis);
    if (orientation < 0)
      start.axis = -start.axis;
  } else {
    start.axis = largest_component_positive(start.axis);
  }
  return refine_best_start({start}, points, weights, fit_subsample(points, normals, weights, 2000), options);
}

} // namespace primitive_edit
