#include "common/fit/reduce_degenerate_cone.h"

#include "common/fit/fit_plane.h"
#include "common/fit/refine_primitive.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/weighted_pca.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace primitive_edit {

double axial_extent(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, const Eigen::Vector3d& axis)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (!weights.size() || weights[i] > 0) {
      const double h = points.row(i).dot(axis);
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
  return hi > lo ? hi - lo : 0.0;
}

bool cone_is_cylinder_within(const Primitive& cone, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                             double tolerance)
{
  // Not "<=": a taper that is not a number is no cone either.
  return cone.type == PrimitiveType::Cone &&
         !(axial_extent(points, weights, cone.axis) * std::tan(cone.half_angle) > tolerance);
}

bool cone_is_plane_within(const Primitive& cone, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                          double tolerance)
{
  if (cone.type != PrimitiveType::Cone || !primitive_is_valid(cone) || points.rows() < 3)
    return false;
  Eigen::MatrixX3d on_cone(points.rows(), 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    on_cone.row(i) = project_onto_primitive(cone, points.row(i).transpose()).point.transpose();
  const WeightedPca pca = weighted_pca(on_cone, weights);
  if (!pca.ok)
    return false;
  const Eigen::Vector3d normal = pca.axes.col(0);
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    // Not "> tolerance": a point that is not a number makes no plane.
    if ((!weights.size() || weights[i] > 0) &&
        !(std::abs((on_cone.row(i).transpose() - pca.centroid).dot(normal)) <= tolerance))
      return false;
  return true;
}

FitResult reduce_degenerate_cone(const FitResult& fit, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                                 double tolerance, const FitOptions& options)
{
  if (fit.status.ok() && cone_is_plane_within(fit.primitive, points, weights, tolerance)) {
    FitResult plane = fit_plane(points, Eigen::MatrixX3d(), weights, options);
    return plane.status.ok() ? plane : fit;
  }
  if (!fit.status.ok() || !cone_is_cylinder_within(fit.primitive, points, weights, tolerance))
    return fit;
  const Primitive& cone = fit.primitive;
  double height = 0, distance = 0, total = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    if (!(w > 0))
      continue;
    const Eigen::Vector3d v = points.row(i).transpose() - cone.origin;
    const double h = v.dot(cone.axis);
    height += w * h;
    distance += w * (v - h * cone.axis).norm();
    total += w;
  }
  if (!(total > 0))
    return fit;
  Primitive cylinder;
  cylinder.type = PrimitiveType::Cylinder;
  cylinder.axis = cone.axis;
  cylinder.origin = cone.origin + height / total * cone.axis;
  cylinder.radius = distance / total;
  if (!primitive_is_valid(cylinder))
    return fit;
  FitResult refined = refine_primitive(cylinder, points, weights, options);
  return refined.status.ok() ? refined : fit;
}

} // namespace primitive_edit
