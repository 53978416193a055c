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

WeightedPca weighted_pca(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights);

} // namespace primitive_edit

#endif
