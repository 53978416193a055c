#include "common/fit/fit_quadric_direct.h"

namespace primitive_edit {

FitResult fit_quadric_direct(PrimitiveType type, const Eigen::MatrixX3d& points,
                             const Eigen::VectorXd& weights)
{
  switch (type) {
  case PrimitiveType::Plane: return fit_plane_direct(points, weights);
  case PrimitiveType::Sphere: return fit_sphere_direct(points, weights);
  case PrimitiveType::Cylinder: return fit_cylinder_direct(points, weights);
  case PrimitiveType::Cone: return fit_cone_direct(points, weights);
  case PrimitiveType::Torus: break;
  }
  FitResult out;
  out.status = Status::failure(std::string("no direct quadric fit for a ") + primitive_type_name(type) +
                               ": it is not a quadric surface");
  return out;
}

} // namespace primitive_edit
