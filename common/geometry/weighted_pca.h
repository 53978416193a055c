// weighted_pca.h: weighted centroid and principal axes of a point set.
//
// Input:  points N x 3, weights N (empty = all 1).
// Output: centroid, eigenvalues of the weighted covariance in increasing order and the matching unit
//         eigenvectors (columns); ok == false when the total weight is not positive.
// Cost:   O(N) plus a 3 x 3 eigen decomposition.
#ifndef PRIMITIVE_EDIT_WEIGHTED_PCA_H
#define PRIMITIVE_EDIT_WEIGHTED_PCA_H

#include <Eigen/Eigenvalues>

namespace primitive_edit {

struct WeightedPca
{
  bool ok = false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
};

inline WeightedPca weighted_pca(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
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

#endif
