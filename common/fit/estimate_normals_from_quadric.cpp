#include "common/fit/estimate_normals_from_quadric.h"

namespace primitive_edit {

Eigen::MatrixX3d estimate_normals_from_quadric(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  using Vec9 = Eigen::Matrix<double, 9, 1>;
  using Mat9 = Eigen::Matrix<double, 9, 9>;
  const Eigen::Index n = points.rows();
  auto weight = [&](Eigen::Index i) { return weights.size() ? weights[i] : 1.0; };
  if (n < 9)
    return {};
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double sum_w = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    centroid += weight(i) * points.row(i).transpose();
    sum_w += weight(i);
  }
  if (!(sum_w > 0))
    return {};
  centroid /= sum_w;
  double spread = 0;
  for (Eigen::Index i = 0; i < n; ++i)
    spread += weight(i) * (points.row(i).transpose() - centroid).squaredNorm();
  spread = std::sqrt(spread / sum_w);
  if (!(spread > 0))
    return {};
  auto local = [&](Eigen::Index i) { return Eigen::Vector3d((points.row(i).transpose() - centroid) / spread); };
  auto monomials = [](const Eigen::Vector3d& p) {
    Vec9 l;
    l << p.x() * p.x(), p.y() * p.y(), p.z() * p.z(), p.x() * p.y(), p.x() * p.z(), p.y() * p.z(), p.x(), p.y(), p.z();
    return l;
  };
  Vec9 mean = Vec9::Zero();
  for (Eigen::Index i = 0; i < n; ++i)
    mean += weight(i) * monomials(local(i));
  mean /= sum_w;
  Mat9 M = Mat9::Zero(), N = Mat9::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = weight(i);
    if (!(w > 0))
      continue;
    const Eigen::Vector3d p = local(i);
    const Vec9 l = monomials(p) - mean;
    M.selfadjointView<Eigen::Lower>().rankUpdate(l, w);
    Eigen::Matrix<double, 9, 3> G = Eigen::Matrix<double, 9, 3>::Zero();
    G(0, 0) = 2 * p.x();
    G(1, 1) = 2 * p.y();
    G(2, 2) = 2 * p.z();
    G(3, 0) = p.y(), G(3, 1) = p.x();
    G(4, 0) = p.z(), G(4, 2) = p.x();
    G(5, 1) = p.z(), G(5, 2) = p.y();
    G(6, 0) = 1, G(7, 1) = 1, G(8, 2) = 1;
    N.selfadjointView<Eigen::Lower>().rankUpdate(G, w);
  }
  M = M.selfadjointView<Eigen::Lower>();
  N = N.selfadjointView<Eigen::Lower>();
  N.diagonal().array() += 1e-12 * N.trace();
  Eigen::GeneralizedSelfAdjointEigenSolver<Mat9> eig(M, N);
  if (eig.info() != Eigen::Success)
    return {};
  const Vec9 c = eig.eigenvectors().col(0);
  if (!c.allFinite())
    return {};
  Eigen::MatrixX3d normals(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d p = local(i);
    const Eigen::Vector3d g(2 * c[0] * p.x() + c[3] * p.y() + c[4] * p.z() + c[6],
                            2 * c[1] * p.y() + c[3] * p.x() + c[5] * p.z() + c[7],
                            2 * c[2] * p.z() + c[4] * p.x() + c[5] * p.y() + c[8]);
    const double len = g.norm();
    normals.row(i) = len > 1e-12 * c.norm() ? Eigen::RowVector3d(g.transpose() / len) : Eigen::RowVector3d::Zero();
  }
  return normals;
}

} // namespace primitive_edit
