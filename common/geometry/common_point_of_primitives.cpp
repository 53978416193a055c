#include "common/geometry/common_point_of_primitives.h"

namespace primitive_edit {

bool common_point_of_primitives(const std::vector<const Primitive*>& primitives, const Eigen::Vector3d& p,
                                double max_distance, Eigen::Vector3d& result)
{
  const int k = static_cast<int>(primitives.size());
  if (k < 3 || !p.allFinite() || !(max_distance > 0))
    return false;
  for (const Primitive* prim : primitives)
    if (!prim || !primitive_is_valid(*prim))
      return false;
  const double scale = 1.0 + p.norm();
  Eigen::MatrixX3d jac(k, 3);
  Eigen::VectorXd f(k);
  auto evaluate = [&](const Eigen::Vector3d& x) {
    for (int i = 0; i < k; ++i) {
      const PrimitiveProjection pr = project_onto_primitive(*primitives[i], x);
      jac.row(i) = pr.normal.transpose();
      f(i) = pr.signed_distance;
    }
  };
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  auto step = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    evaluate(x);
    const Eigen::VectorXd r = f + jac * (p - x);
    // Pseudo-inverse through the 3x3 normal matrix; directions with (almost) no constraint are left free,
    // which keeps them at p's coordinates: the nearest solution.
    eig.compute(jac.transpose() * jac);
    const Eigen::Vector3d ev = eig.eigenvalues();
    const double cutoff = 1e-12 * ev.maxCoeff();
    Eigen::Vector3d inv = Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i)
      if (ev(i) > cutoff)
        inv(i) = 1.0 / ev(i);
    const Eigen::Matrix3d& v = eig.eigenvectors();
    return p - v * inv.asDiagonal() * v.transpose() * (jac.transpose() * r);
  };
  Eigen::Vector3d x;
  if (!iterate_to_nearest_solution(p, max_distance, step, x))
    return false;
  evaluate(x);
  if (f.cwiseAbs().maxCoeff() > 1e-10 * scale)
    return false;
  eig.compute(jac.transpose() * jac, Eigen::EigenvaluesOnly);
  // Eigenvalues are sorted increasingly: the first is the smallest squared singular value.
  if (!(std::sqrt(std::max(0.0, eig.eigenvalues()(0))) >= kMinSurfaceSine))
    return false;
  if ((x - p).norm() > max_distance)
    return false;
  result = x;
  return true;
}

} // namespace primitive_edit
