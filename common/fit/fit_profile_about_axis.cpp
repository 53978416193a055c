#include "common/fit/fit_profile_about_axis.h"

#include "common/geometry/fit_circle_2d.h"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace primitive_edit {

namespace {

// The points of positive weight in the meridian half-plane: r from the axis, h along it.
struct Profile
{
  Eigen::VectorXd r, h, w;
};

Profile meridian(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, const Eigen::Vector3d& axis_point,
                 const Eigen::Vector3d& axis)
{
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (!weights.size() || weights[i] > 0)
      kept.push_back(i);
  Profile p;
  p.r.resize(Eigen::Index(kept.size()));
  p.h.resize(p.r.size());
  p.w.resize(p.r.size());
  for (Eigen::Index k = 0; k < p.r.size(); ++k) {
    const Eigen::Index i = kept[std::size_t(k)];
    const Eigen::Vector3d d = points.row(i).transpose() - axis_point;
    p.h[k] = d.dot(axis);
    p.r[k] = (d - p.h[k] * axis).norm();
    p.w[k] = weights.size() ? weights[i] : 1.0;
  }
  return p;
}

// Gauss-Newton on sum w (|(r, h) - (a, c)| - R)^2 over (a, c, R), a held at 0 when on_axis.
bool refine_circle(const Profile& p, bool on_axis, double& a, double& c, double& R)
{
  const int n = on_axis ? 2 : 3;
  for (int iteration = 0; iteration < kProfileIterations; ++iteration) {
    Eigen::Matrix3d JtJ = Eigen::Matrix3d::Zero();
    Eigen::Vector3d Jtd = Eigen::Vector3d::Zero();
    for (Eigen::Index i = 0; i < p.r.size(); ++i) {
      const double dr = p.r[i] - a, dh = p.h[i] - c, q = std::hypot(dr, dh);
      if (!(q > 0))
        continue;
      // Rows in the order (c, R, a): the on-axis fit uses the first two.
      const Eigen::Vector3d J(-dh / q, -1.0, -dr / q);
      JtJ += p.w[i] * J * J.transpose();
      Jtd += p.w[i] * J * (q - R);
    }
    const Eigen::VectorXd step = JtJ.topLeftCorner(n, n).ldlt().solve(-Jtd.head(n));
    if (!step.allFinite())
      return false;
    c += step[0];
    R += step[1];
    if (!on_axis)
      a += step[2];
    if (step.norm() <= 1e-12 * (std::abs(R) + std::abs(c) + std::abs(a)))
      break;
  }
  return std::isfinite(a) && std::isfinite(c) && std::isfinite(R) && R > 0;
}

std::optional<Primitive> fit_circle_profile(const Profile& p, bool on_axis, const Eigen::Vector3d& axis_point,
                                            const Eigen::Vector3d& axis)
{
  double a = 0, c = 0, R = 0;
  if (on_axis) {
    // Kasa with the centre at height c: r^2 + h^2 = 2 c h + (R^2 - c^2), linear in (c, k).
    Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    for (Eigen::Index i = 0; i < p.r.size(); ++i) {
      const Eigen::Vector2d row(2 * p.h[i], 1.0);
      M += p.w[i] * row * row.transpose();
      b += p.w[i] * row * (p.r[i] * p.r[i] + p.h[i] * p.h[i]);
    }
    const Eigen::Vector2d x = M.ldlt().solve(b);
    c = x[0];
    if (!(x[1] + c * c > 0))
      return std::nullopt;
    R = std::sqrt(x[1] + c * c);
  } else {
    Eigen::MatrixX2d rh(p.r.size(), 2);
    rh.col(0) = p.r;
    rh.col(1) = p.h;
    const Circle2d start = fit_circle_2d(rh, p.w);
    if (!start.ok)
      return std::nullopt;
    a = start.centre.x();
    c = start.centre.y();
    R = start.radius;
  }
  if (!refine_circle(p, on_axis, a, c, R))
    return std::nullopt;
  Primitive out;
  out.type = on_axis ? PrimitiveType::Sphere : PrimitiveType::Torus;
  out.origin = axis_point + c * axis;
  out.axis = axis;
  out.radius = on_axis ? R : a;
  out.minor_radius = on_axis ? 0.0 : R;
  return out;
}

std::optional<Primitive> fit_cone_profile(const Profile& p, const Eigen::Vector3d& axis_point,
                                          const Eigen::Vector3d& axis)
{
  const double sum_w = p.w.sum();
  const Eigen::Vector2d mean(p.w.dot(p.r) / sum_w, p.w.dot(p.h) / sum_w);
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (Eigen::Index i = 0; i < p.r.size(); ++i) {
    const Eigen::Vector2d q = Eigen::Vector2d(p.r[i], p.h[i]) - mean;
    cov += p.w[i] * q * q.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  Eigen::Vector2d t = eig.eigenvectors().col(1);
  if (t.x() < 0)
    t = -t;  // towards the opening
  if (!(t.x() > 1e-9 && std::abs(t.y()) > 1e-9))
    return std::nullopt;
  Primitive out;
  out.type = PrimitiveType::Cone;
  out.origin = axis_point + (mean.y() - mean.x() * t.y() / t.x()) * axis;
  out.axis = t.y() > 0 ? axis : Eigen::Vector3d(-axis);
  out.half_angle = std::atan2(t.x(), std::abs(t.y()));
  return out;
}

} // namespace

std::optional<Primitive> fit_profile_about_axis(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights,
                                                const Eigen::Vector3d& axis_point, const Eigen::Vector3d& axis,
                                                PrimitiveType type)
{
  const int dof = profile_degrees_of_freedom(type);
  if (dof == 0 || (weights.size() && weights.size() != points.rows()) || !axis_point.allFinite() ||
      !(std::abs(axis.norm() - 1.0) < 1e-6))
    return std::nullopt;
  const Profile p = meridian(points, weights, axis_point, axis);
  if (p.r.size() < std::max(3, dof + 1) || !p.r.allFinite() || !p.h.allFinite() || !(p.w.sum() > 0) ||
      !std::isfinite(p.w.sum()))
    return std::nullopt;
  std::optional<Primitive> out;
  switch (type) {
  case PrimitiveType::Cylinder: {
    Primitive c;
    c.type = PrimitiveType::Cylinder;
    c.origin = axis_point;
    c.axis = axis;
    c.radius = p.w.dot(p.r) / p.w.sum();
    out = c;
    break;
  }
  case PrimitiveType::Cone: out = fit_cone_profile(p, axis_point, axis); break;
  case PrimitiveType::Sphere: out = fit_circle_profile(p, true, axis_point, axis); break;
  case PrimitiveType::Torus: out = fit_circle_profile(p, false, axis_point, axis); break;
  case PrimitiveType::Plane: break;
  }
  if (out && !primitive_is_valid(*out))
    return std::nullopt;
  return out;
}

} // namespace primitive_edit
