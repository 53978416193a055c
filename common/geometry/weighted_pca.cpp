#include "common/geometry/weighted_pca.h"

namespace primitive_edit {

WeightedPca weighted_pca(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  WeightedPca out;
  double sum_w = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    out.centroid += w * points.row(i).transpose();
    sum_w += w;
  }
  if (!(sum_w > 0))
    return out;
  out.centroid /= sum_w;
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    const Eigen::Vector3d d = points.row(i).transpose() - out.centroid;
    C += w * d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C / sum_w);
  out.eigenvalues = eig.eigenvalues();
  out.axes = eig.eigenvectors();
  out.ok = out.eigenvalues.allFinite() && out.axes.allFinite();
  return out;
}

} // namespace primitive_edit
