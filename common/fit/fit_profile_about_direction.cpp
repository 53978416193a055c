#include "common/fit/fit_profile_about_direction.h"

#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/fit_circle_2d.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace primitive_edit {

namespace {

// The profile fitted about the axis through `origin` and the points' weighted distances to it.
struct Evaluation
{
  std::optional<Primitive> primitive;
  Eigen::VectorXd residual;
  double cost = std::numeric_limits<double>::infinity();
};

Evaluation evaluate(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, const Eigen::Vector3d& origin,
                    const Eigen::Vector3d& direction, PrimitiveType type)
{
  Evaluation e;
  e.primitive = fit_profile_about_axis(points, weights, origin, direction, type);
  if (!e.primitive)
    return e;
  e.residual.resize(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    e.residual[i] = std::sqrt(w) * project_onto_primitive(*e.primitive, points.row(i).transpose()).signed_distance;
  }
  e.cost = e.residual.squaredNorm();
  if (!std::isfinite(e.cost))
    e.primitive.reset();
  return e;
}

} // namespace

std::optional<Primitive> fit_profile_about_direction(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                                                     const Eigen::Vector3d& direction, PrimitiveType type)
{
  if (type == PrimitiveType::Sphere || (weights.size() && weights.size() != points.rows()) ||
      !direction.allFinite() || !(std::abs(direction.norm() - 1.0) < 1e-6) || points.rows() < 3 ||
      !points.allFinite() || (weights.size() && !(weights.minCoeff() >= 0 && weights.sum() > 0)))
    return std::nullopt;
  if (type == PrimitiveType::Plane) {
    const Eigen::VectorXd w = weights.size() ? weights : Eigen::VectorXd::Ones(points.rows());
    Primitive plane;
    plane.origin = (w.transpose() * points).transpose() / w.sum();
    plane.axis = direction;
    return primitive_is_valid(plane) ? std::optional<Primitive>(plane) : std::nullopt;
  }
  // The plane across the direction, and the points projected into it.
  const Eigen::Vector3d u = any_orthogonal(direction), v = direction.cross(u);
  Eigen::MatrixX2d across(points.rows(), 2);
  across.col(0) = points * u;
  across.col(1) = points * v;
  const Circle2d start = fit_circle_2d(across, weights);
  if (!start.ok)
    return std::nullopt;
  const double scale = (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  const auto origin = [&](const Eigen::Vector2d& c) -> Eigen::Vector3d { return c.x() * u + c.y() * v; };

  Eigen::Vector2d c = start.centre;
  Evaluation now = evaluate(points, weights, origin(c), direction, type);
  if (!now.primitive)
    return std::nullopt;
  const double h = 1e-5 * std::max(scale, start.radius);
  double lambda = 1e-3;
  for (int iteration = 0; iteration < kDirectionIterations; ++iteration) {
    Eigen::MatrixX2d J(points.rows(), 2);
    bool differentiable = true;
    for (int k = 0; k < 2 && differentiable; ++k) {
      const Evaluation moved = evaluate(points, weights, origin(c + h * Eigen::Vector2d::Unit(k)), direction, type);
      differentiable = moved.primitive.has_value();
      if (differentiable)
        J.col(k) = (moved.residual - now.residual) / h;
    }
    if (!differentiable)
      break;
    const Eigen::Matrix2d A = J.transpose() * J;
    const Eigen::Vector2d g = J.transpose() * now.residual;
    bool improved = false;
    Eigen::Vector2d step = Eigen::Vector2d::Zero();
    while (!improved && lambda < 1e12) {
      Eigen::Matrix2d damped = A;
      damped.diagonal() *= 1 + lambda;
      step = damped.ldlt().solve(-g);
      if (!step.allFinite())
        break;
      Evaluation next = evaluate(points, weights, origin(c + step), direction, type);
      if (next.primitive && next.cost < now.cost) {
        c += step;
        now = std::move(next);
        lambda = std::max(lambda * 0.1, 1e-12);
        improved = true;
      } else {
        lambda *= 10;
      }
    }
    if (!improved || step.norm() <= 1e-9 * scale)
      break;
  }
  return now.primitive;
}

} // namespace primitive_edit
