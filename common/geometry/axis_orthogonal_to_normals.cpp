#include "common/geometry/axis_orthogonal_to_normals.h"

namespace primitive_edit {

bool axis_orthogonal_to_normals(const Eigen::MatrixX3d& normals, const Eigen::VectorXd& weights,
                                Eigen::Vector3d* axis)
{
  if (!normals.rows())
    return false;
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < normals.rows(); ++i)
    S += (weights.size() ? weights[i] : 1.0) * normals.row(i).transpose() * normals.row(i);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(S);
  if (!(eig.eigenvalues()[1] > 1e-9 * eig.eigenvalues()[2]))
    return false;
  *axis = eig.eigenvectors().col(0).normalized();
  return axis->allFinite();
}

} // namespace primitive_edit
