#include "common/fit/fit_plane_direct.h"

namespace primitive_edit {

FitResult fit_plane_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  FitResult out;
  out.status = quadric_direct::check_direct_input(PrimitiveType::Plane, points, weights);
  if (!out.status)
    return out;
  const WeightedPca pca = weighted_pca(points, weights);
  Primitive p;
  p.type = PrimitiveType::Plane;
  p.origin = pca.centroid;
  p.axis = pca.axes.col(0).normalized();
  p.axis = largest_component_positive(p.axis);
  return quadric_direct::direct_fit_result(p, points, weights);
}

} // namespace primitive_edit
