#include "common/fit/fit_sphere_direct.h"

namespace primitive_edit {

FitResult fit_sphere_direct(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  FitResult out;
  out.status = quadric_direct::check_direct_input(PrimitiveType::Sphere, points, weights);
  if (!out.status)
    return out;
  Primitive p;
  if (!fit_sphere_detail::taubin_sphere(points, weights, &p)) {
    out.status = Status::failure("the points determine no sphere (the algebraic fit is a plane)");
    return out;
  }
  const double extent = quadric_direct::data_extent(points);
  if (p.radius > 1e4 * extent) {
    out.status = Status::failure("points are (nearly) coplanar: sphere radius " + std::to_string(p.radius) +
                                 " exceeds 1e4 times the data extent");
    return out;
  }
  return quadric_direct::direct_fit_result(p, points, weights);
}

} // namespace primitive_edit
