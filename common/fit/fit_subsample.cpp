#include "common/fit/fit_subsample.h"

namespace primitive_edit {

FitSample fit_subsample(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
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
