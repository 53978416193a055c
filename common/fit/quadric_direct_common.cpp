#include "common/fit/quadric_direct_common.h"

namespace primitive_edit {

namespace quadric_direct {

Vec9 monomials(const Eigen::Vector3d& q)
{
  Vec9 l;
  l << q.x() * q.x(), q.y() * q.y(), q.z() * q.z(), q.x() * q.y(), q.x() * q.z(), q.y() * q.z(), q.x(), q.y(), q.z();
  return l;
}

Vec9 coefficients(const Eigen::Matrix3d& A, const Eigen::Vector3d& b)
{
  Vec9 c;
  c << A(0, 0), A(1, 1), A(2, 2), 2 * A(0, 1), 2 * A(0, 2), 2 * A(1, 2), b.x(), b.y(), b.z();
  return c;
}

QuadricMoments quadric_moments(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  QuadricMoments m;
  auto weight = [&](Eigen::Index i) { return weights.size() ? weights[i] : 1.0; };
  double sum_w = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    m.centroid += weight(i) * points.row(i).transpose();
    sum_w += weight(i);
  }
  if (!(sum_w > 0))
    return m;
  m.centroid /= sum_w;
  double spread = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    spread += weight(i) * (points.row(i).transpose() - m.centroid).squaredNorm();
  m.scale = std::sqrt(spread / sum_w);
  if (!(m.scale > 0))
    return m;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    m.mean += weight(i) * monomials((points.row(i).transpose() - m.centroid) / m.scale);
  m.mean /= sum_w;
  // At least 9 rows (zero padded) so that R is 9 x 9 for the smallest inputs too.
  Eigen::Matrix<double, Eigen::Dynamic, 9> D =
      Eigen::Matrix<double, Eigen::Dynamic, 9>::Zero(std::max<Eigen::Index>(points.rows(), 9), 9);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weight(i);
    if (!(w > 0))
      continue;
    const Eigen::Vector3d q = (points.row(i).transpose() - m.centroid) / m.scale;
    D.row(i) = std::sqrt(w) * (monomials(q) - m.mean).transpose();
    Eigen::Matrix<double, 9, 3> G = Eigen::Matrix<double, 9, 3>::Zero();
    G(0, 0) = 2 * q.x(), G(1, 1) = 2 * q.y(), G(2, 2) = 2 * q.z();
    G(3, 0) = q.y(), G(3, 1) = q.x();
    G(4, 0) = q.z(), G(4, 2) = q.x();
    G(5, 1) = q.z(), G(5, 2) = q.y();
    G(6, 0) = 1, G(7, 1) = 1, G(8, 2) = 1;
    m.N.selfadjointView<Eigen::Lower>().rankUpdate(G, w);
  }
  // The design matrix itself, not M = D^T D, keeps the algebraic cost accurate to ~1e-32 instead of
  // ~1e-16 near an exact fit: M's round-off alone would shift the best axis by sqrt(1e-16 / curvature).
  m.R = Eigen::HouseholderQR<Eigen::Matrix<double, Eigen::Dynamic, 9>>(D).matrixQR().topRows<9>().triangularView<Eigen::Upper>();
  m.N = m.N.selfadjointView<Eigen::Lower>();
  m.ok = m.R.allFinite() && m.N.allFinite();
  return m;
}

Eigen::Vector3d unconstrained_axis(const QuadricMoments& m)
{
  const Vec9 c = pencil_minimum<9>(m, Mat9::Identity(), true).theta;
  Eigen::Matrix3d A;
  A << c[0], c[3] / 2, c[4] / 2, c[3] / 2, c[1], c[5] / 2, c[4] / 2, c[5] / 2, c[2];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);
  const Eigen::Vector3d& l = eig.eigenvalues();
  return eig.eigenvectors().col(l[1] - l[0] < l[2] - l[1] ? 2 : 0);
}

Status check_direct_input(PrimitiveType type, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  const Status input = check_fit_input(points, Eigen::MatrixX3d(), weights, minimum_points_for(type));
  if (!input)
    return input;
  const WeightedPca pca = weighted_pca(points, weights);
  if (!pca.ok || !(pca.eigenvalues[1] > 1e-12 * pca.eigenvalues[2]))
    return Status::failure("points are collinear or coincident: no " + std::string(primitive_type_name(type)));
  if (type != PrimitiveType::Plane && !(pca.eigenvalues[0] > 1e-12 * pca.eigenvalues[2]))
    return Status::failure("points are coplanar: no " + std::string(primitive_type_name(type)));
  return Status::success();
}

QuadricMoments checked_quadric_moments(PrimitiveType type, const Eigen::MatrixX3d& points,
                                       const Eigen::VectorXd& weights, Status& status)
{
  status = check_direct_input(type, points, weights);
  if (!status)
    return QuadricMoments();
  const QuadricMoments m = quadric_moments(points, weights);
  if (!m.ok)
    status = Status::failure("the points' quadric moments are not finite");
  return m;
}

double data_extent(const Eigen::MatrixX3d& points)
{
  return (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
}

FitResult direct_fit_result(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  if (!primitive_is_valid(p)) {
    FitResult out;
    out.primitive = p;
    out.status = Status::failure("the fitted quadric gives no valid " + std::string(primitive_type_name(p.type)));
    return out;
  }
  return fit_residuals(canonicalize_primitive(p, points, weights), points, weights);
}

} // namespace quadric_direct
} // namespace primitive_edit
