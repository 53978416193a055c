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

inline FitSample fit_subsample(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                               const Eigen::VectorXd& weights, Eigen::Index max_count)
{
  FitSample s;
  const Eigen::Index n = points.rows();
  if (n <= max_count || max_count <= 0) {
    s.points = points;
    s.normals = normals;
    s.weights = weights;
    return s;
  }
  s.points.resize(max_count, 3);
  if (normals.rows())
    s.normals.resize(max_count, 3);
  if (weights.size())
    s.weights.resize(max_count);
  for (Eigen::Index i = 0; i < max_count; ++i) {
    const Eigen::Index j = static_cast<Eigen::Index>((static_cast<double>(i) * n) / max_count);
    s.points.row(i) = points.row(j);
    if (normals.rows())
      s.normals.row(i) = normals.row(j);
    if (weights.size())
      s.weights[i] = weights[j];
  }
  return s;
}

} // namespace primitive_edit

#endif
