// axis_orthogonal_to_normals.h: the direction most orthogonal to a set of normals.
//
// Input:  normals N x 3 (zero rows are ignored), weights N (empty = all 1).
// Output: the unit a minimising sum w (n . a)^2, i.e. the smallest eigenvector of sum w n n^T: the
//         axis of a cylinder (its normals are orthogonal to the axis). false when there are no
//         normals or they do not span two directions (a plane's normals).
// Cost:   O(N).
#ifndef PRIMITIVE_EDIT_AXIS_ORTHOGONAL_TO_NORMALS_H
#define PRIMITIVE_EDIT_AXIS_ORTHOGONAL_TO_NORMALS_H

#include <Eigen/Eigenvalues>

namespace primitive_edit {

bool axis_orthogonal_to_normals(const Eigen::MatrixX3d& normals, const Eigen::VectorXd& weights,
                                Eigen::Vector3d* axis);

} // namespace primitive_edit

#endif
