// fit_subsample.h: a deterministic, evenly strided subsample of a fit's input.
//
// Input:  points N x 3, normals (N x 3 or empty), weights (N or empty), the largest count wanted.
// Output: the rows i * N / count (i = 0 .. count-1) of each array (all rows when N <= max_count);
//         empty arrays stay empty. Scan segments are stored in mesh order, so a stride keeps the
//         spatial spread; no randomness, so fits are reproducible.
// Cost:   O(min(N, max_count)).
#ifndef PRIMITIVE_EDIT_FIT_SUBSAMPLE_H
#define PRIMITIVE_EDIT_FIT_SUBSAMPLE_H

#include <Eigen/Core>

namespace primitive_edit {

struct FitSample
{
  Eigen::MatrixX3d points, normals;
  Eigen::VectorXd weights;
};

FitSample fit_subsample(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                        const Eigen::VectorXd& weights, Eigen::Index max_count);

} // namespace primitive_edit

#endif
