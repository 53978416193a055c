#include "common/fit/fit_primitive.h"

namespace primitive_edit {

FitResult fit_primitive(PrimitiveType type, const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                        const Eigen::VectorXd& weights, const FitOptions& options)
{
  if (options.method != FitMethod::Refined && type != PrimitiveType::Torus) {
    const FitResult direct = fit_quadric_direct(type, points, weights);
    if (!direct.status.ok() || options.method == FitMethod::Direct)
      return direct;
    return refine_primitive(direct.primitive, points, weights, options);
  }
  switch (type) {
  case PrimitiveType::Plane: return fit_plane(points, normals, weights, options);
  case PrimitiveType::Sphere: return fit_sphere(points, normals, weights, options);
  case PrimitiveType::Cylinder: return fit_cylinder(points, normals, weights, options);
  case PrimitiveType::Cone: return fit_cone(points, normals, weights, options);
  case PrimitiveType::Torus: return fit_torus(points, normals, weights, options);
  }
  FitResult out;
  out.status = Status::failure("unknown primitive type");
  return out;
}

} // namespace primitive_edit
