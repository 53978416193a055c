#include "common/fit/refine_primitive.h"

namespace primitive_edit {

namespace refine_detail {

LocalFrame local_frame(const Primitive& p)
{
  LocalFrame f;
  f.e1 = any_orthogonal(p.axis);
  f.e2 = p.axis.cross(f.e1);
  if (p.type == PrimitiveType::Cone) {
    f.cos_angle = std::cos(p.half_angle);
    f.sin_angle = std::sin(p.half_angle);
  }
  return f;
}

namespace {

template <PrimitiveType T>
using TypeVector = Eigen::Matrix<double, primitive_degrees_of_freedom(T), 1>;

// The residual of one type, its Jacobian over that type's parameters only: the refinement's inner loop, without
// a switch or the other parameters' zeros per point.
template <PrimitiveType T>
double typed_residual(const Primitive& p, const LocalFrame& frame, const Eigen::Vector3d& x, TypeVector<T>* J)
{
  const Eigen::Vector3d v = x - p.origin;
  const Eigen::Vector3d& a = p.axis;
  const Eigen::Vector3d& e1 = frame.e1;
  const Eigen::Vector3d& e2 = frame.e2;
  if constexpr (T == PrimitiveType::Plane) {
    if (J)
      *J << -1.0, v.dot(e1), v.dot(e2);
    return v.dot(a);
  } else if constexpr (T == PrimitiveType::Sphere) {
    const double n = v.norm();
    const Eigen::Vector3d u = n > 1e-300 ? Eigen::Vector3d(v / n) : Eigen::Vector3d::UnitZ();
    if (J)
      *J << -u.x(), -u.y(), -u.z(), -1.0;
    return n - p.radius;
  } else if constexpr (T == PrimitiveType::Cylinder) {
    const double h = v.dot(a);
    double rho = 0;
    const Eigen::Vector3d u = radial_direction(v, a, &rho);
    if (J) {
      const double u1 = u.dot(e1), u2 = u.dot(e2);
      *J << -u1, -u2, -h * u1, -h * u2, -1.0;
    }
    return rho - p.radius;
  } else if constexpr (T == PrimitiveType::Cone) {
    const double h = v.dot(a);
    double rho = 0;
    const Eigen::Vector3d u = radial_direction(v, a, &rho);
    const double c = frame.cos_angle, s = frame.sin_angle;
    if (h * c + rho * s > 0) {
      if (J) {
        const Eigen::Vector3d g = s * a - c * u;
        *J << g.x(), g.y(), g.z(), -s * v.dot(e1) - c * h * u.dot(e1), -s * v.dot(e2) - c * h * u.dot(e2),
            -h * c - rho * s;
      }
      return -h * s + rho * c;
    }
    const double n = v.norm();
    if (J) {
      const Eigen::Vector3d g = n > 1e-300 ? Eigen::Vector3d(-v / n) : Eigen::Vector3d::Zero();
      *J << g.x(), g.y(), g.z(), 0, 0, 0;
    }
    return n;
  } else {
    const double h = v.dot(a);
    double rho = 0;
    const Eigen::Vector3d u = radial_direction(v, a, &rho);
    const double dr = rho - p.radius;
    const double dist = std::sqrt(dr * dr + h * h);
    const double wr = dist > 1e-300 ? dr / dist : 1.0, wh = dist > 1e-300 ? h / dist : 0.0;
    if (J) {
      const Eigen::Vector3d g = -(wr * u + wh * a);
      *J << g.x(), g.y(), g.z(), -wr * h * u.dot(e1) + wh * v.dot(e1), -wr * h * u.dot(e2) + wh * v.dot(e2),
          -wr, -1.0;
    }
    return dist - p.minor_radius;
  }
}

template <PrimitiveType T>
double residual_in_vec7(const Primitive& p, const LocalFrame& frame, const Eigen::Vector3d& x, Vec7* J)
{
  if (!J)
    return typed_residual<T>(p, frame, x, nullptr);
  TypeVector<T> typed;
  const double r = typed_residual<T>(p, frame, x, &typed);
  J->setZero();
  J->template head<primitive_degrees_of_freedom(T)>() = typed;
  return r;
}

} // namespace

double residual(const Primitive& p, const LocalFrame& frame, const Eigen::Vector3d& x, Vec7* J)
{
  switch (p.type) {
  case PrimitiveType::Plane: return residual_in_vec7<PrimitiveType::Plane>(p, frame, x, J);
  case PrimitiveType::Sphere: return residual_in_vec7<PrimitiveType::Sphere>(p, frame, x, J);
  case PrimitiveType::Cylinder: return residual_in_vec7<PrimitiveType::Cylinder>(p, frame, x, J);
  case PrimitiveType::Cone: return residual_in_vec7<PrimitiveType::Cone>(p, frame, x, J);
  case PrimitiveType::Torus: return residual_in_vec7<PrimitiveType::Torus>(p, frame, x, J);
  }
  return 0;
}

bool apply_step(const Primitive& p, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, const Vec7& d,
                Primitive* out)
{
  Primitive q = p;
  auto rotate = [&](double t1, double t2) { q.axis = (p.axis + t1 * e1 + t2 * e2).normalized(); };
  switch (p.type) {
  case PrimitiveType::Plane:
    q.origin = p.origin + d[0] * p.axis;
    rotate(d[1], d[2]);
    break;
  case PrimitiveType::Sphere:
    q.origin = p.origin + d.head<3>();
    q.radius = p.radius + d[3];
    break;
  case PrimitiveType::Cylinder:
    q.origin = p.origin + d[0] * e1 + d[1] * e2;
    rotate(d[2], d[3]);
    q.radius = p.radius + d[4];
    break;
  case PrimitiveType::Cone:
    q.origin = p.origin + d.head<3>();
    rotate(d[3], d[4]);
    q.half_angle = p.half_angle + d[5];
    break;
  case PrimitiveType::Torus:
    q.origin = p.origin + d.head<3>();
    rotate(d[3], d[4]);
    q.radius = p.radius + d[5];
    q.minor_radius = p.minor_radius + d[6];
    break;
  }
  if (!primitive_is_valid(q))
    return false;
  *out = q;
  return true;
}

namespace {

// The normal equations over the type's own parameters only: a plane's 3 x 3 block is a fifth of the 7 x 7 product
// (which took a quarter of a segmentation's instructions). The fixed-size outer product is unrolled and
// vectorised, several times faster than a triangular rank update through Eigen's generic path.
template <PrimitiveType T>
double typed_normal_equations(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w,
                              Mat7* JtJ, Vec7* Jtr)
{
  constexpr int K = primitive_degrees_of_freedom(T);
  const LocalFrame frame = local_frame(p);
  Eigen::Matrix<double, K, K> H = Eigen::Matrix<double, K, K>::Zero();
  TypeVector<T> g = TypeVector<T>::Zero();
  TypeVector<T> J;
  double cost = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (!(w[i] > 0))
      continue;
    const double r = typed_residual<T>(p, frame, points.row(i).transpose(), &J);
    const TypeVector<T> wJ = w[i] * J;
    H.noalias() += wJ * J.transpose();
    g += r * wJ;
    cost += w[i] * r * r;
  }
  JtJ->setZero();
  Jtr->setZero();
  JtJ->template topLeftCorner<K, K>() = H;
  Jtr->template head<K>() = g;
  return cost;
}

} // namespace

double normal_equations(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w,
                        Mat7* JtJ, Vec7* Jtr)
{
  switch (p.type) {
  case PrimitiveType::Plane: return typed_normal_equations<PrimitiveType::Plane>(p, points, w, JtJ, Jtr);
  case PrimitiveType::Sphere: return typed_normal_equations<PrimitiveType::Sphere>(p, points, w, JtJ, Jtr);
  case PrimitiveType::Cylinder: return typed_normal_equations<PrimitiveType::Cylinder>(p, points, w, JtJ, Jtr);
  case PrimitiveType::Cone: return typed_normal_equations<PrimitiveType::Cone>(p, points, w, JtJ, Jtr);
  case PrimitiveType::Torus: return typed_normal_equations<PrimitiveType::Torus>(p, points, w, JtJ, Jtr);
  }
  JtJ->setZero();
  Jtr->setZero();
  return 0;
}

Primitive levenberg_marquardt(Primitive p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w,
                              int max_iterations, double exact_rms)
{
  const int k = primitive_degrees_of_freedom(p.type);
  Mat7 JtJ;
  Vec7 Jtr;
  double cost = normal_equations(p, points, w, &JtJ, &Jtr);
  const double exact_cost = exact_rms * exact_rms * w.sum();
  double lambda = 1e-4;
  for (int it = 0; it < max_iterations && cost > exact_cost; ++it) {
    const Eigen::Vector3d e1 = any_orthogonal(p.axis), e2 = p.axis.cross(e1);
    const Eigen::MatrixXd H = JtJ.topLeftCorner(k, k);
    const Eigen::VectorXd g = Jtr.head(k);
    const double diag_floor = 1e-12 * std::max(H.diagonal().maxCoeff(), 1e-300);
    bool accepted = false;
    for (int attempt = 0; attempt < 6 && !accepted; ++attempt) {
      Eigen::MatrixXd A = H;
      A.diagonal() += lambda * (H.diagonal().array() + diag_floor).matrix();
      const Eigen::VectorXd step = A.ldlt().solve(-g);
      Vec7 d = Vec7::Zero();
      d.head(k) = step;
      Primitive cand;
      if (step.allFinite() && apply_step(p, e1, e2, d, &cand)) {
        Mat7 cand_JtJ;
        Vec7 cand_Jtr;
        const double c = normal_equations(cand, points, w, &cand_JtJ, &cand_Jtr);
        if (c < cost) {
          // Converged when the cost stalls (noisy data: the minimum is reached).
          const bool converged = cost - c <= 1e-9 * cost;
          p = cand;
          cost = c;
          JtJ = cand_JtJ;
          Jtr = cand_Jtr;
          lambda = std::max(lambda * 0.1, 1e-9);
          accepted = true;
          if (converged)
            return p;
          continue;
        }
      }
      lambda *= 10;
    }
    if (!accepted)
      break;
  }
  return p;
}

double median_abs(std::vector<double> v)
{
  if (v.empty())
    return 0;
  auto mid = v.begin() + v.size() / 2;
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

Eigen::VectorXd tukey_weights(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w,
                              double wide, double floor)
{
  const LocalFrame frame = local_frame(p);
  Eigen::VectorXd r(points.rows());
  std::vector<double> abs_r;
  abs_r.reserve(static_cast<size_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    r[i] = std::abs(residual(p, frame, points.row(i).transpose(), nullptr));
    if (w[i] > 0)
      abs_r.push_back(r[i]);
  }
  const double c = std::max(wide * 4.685 * 1.4826 * median_abs(abs_r), floor);
  Eigen::VectorXd out(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double t = r[i] / c;
    out[i] = (w[i] > 0 && t < 1) ? w[i] * (1 - t * t) * (1 - t * t) : 0.0;
  }
  return out;
}

} // namespace refine_detail

FitResult refine_primitive(const Primitive& start, const Eigen::MatrixX3d& points,
                           const Eigen::VectorXd& weights, const FitOptions& options,
                           int max_rounds)
{
  using namespace refine_detail;
  FitResult failed;
  failed.primitive = start;
  if (!primitive_is_valid(start)) {
    failed.status = Status::failure("invalid start primitive");
    return failed;
  }
  failed.status = check_fit_input(points, {}, weights, 1);
  if (!failed.status)
    return failed;
  const Eigen::VectorXd w = weights.size() ? weights : Eigen::VectorXd::Ones(points.rows());
  double extent = 0;
  if (points.rows())
    extent = (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  const double exact_rms = 1e-13 * extent;
  // A rough start is first brought near the data; a robust subsample fit is not (outliers would pull it).
  const bool from_robust_fit = options.robust && max_rounds < 6;
  Primitive p = from_robust_fit ? start : levenberg_marquardt(start, points, w, options.max_iterations, exact_rms);
  Eigen::VectorXd used = w;
  if (options.robust) {
    // Residuals below this are round-off: never reject points for them (exact data).
    const double floor = 1e-9 * std::max(extent, 1e-300);
    const Eigen::Index min_kept = primitive_degrees_of_freedom(p.type) + 1;
    // Wide first rounds let a rough start pull in its inliers before the tight rounds.
    const double widths[] = {4.0, 2.0, 1.0, 1.0, 1.0, 1.0};
    // A start that is already the robust fit of a subsample (refine_best_start.h) needs no wide rounds.
    const int first = max_rounds < 6 ? 2 : 0;
    for (int round = first; round < std::min(6, first + max_rounds); ++round) {
      const double wide = widths[round];
      const Eigen::VectorXd tw = tukey_weights(p, points, w, wide, floor);
      if ((tw.array() > 0).count() < min_kept)
        break;
      const bool same_inliers = ((tw.array() > 0) == (used.array() > 0)).all();
      used = tw;
      if (wide == 1.0 && same_inliers)
        break;
      p = levenberg_marquardt(p, points, used, options.max_iterations, exact_rms);
    }
    // Report over the inliers of the final primitive, with the caller's weights.
    const Eigen::VectorXd tw = tukey_weights(p, points, w, 1.0, floor);
    if ((tw.array() > 0).count() >= min_kept)
      used = tw;
    for (Eigen::Index i = 0; i < w.size(); ++i)
      used[i] = used[i] > 0 ? w[i] : 0.0;
  }
  p = canonicalize_primitive(p, points, used);
  return fit_residuals(p, points, used);
}

} // namespace primitive_edit
