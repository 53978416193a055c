#include "common/geometry/weighted_pca.h"

namespace primitive_edit {

namespace {

// The weighted sums, with w(i) the weight of point i. Only the lower triangle of the covariance is summed: it is
// all the eigen solver reads.
template <class Weight>
WeightedPca pca_of(const Eigen::MatrixX3d& points, Weight w)
{
  WeightedPca out;
  const Eigen::Index n = points.rows();
  double sum_w = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    out.centroid += w(i) * points.row(i).transpose();
    sum_w += w(i);
  }
  if (!(sum_w > 0))
    return out;
  out.centroid /= sum_w;
  double c00 = 0, c10 = 0, c20 = 0, c11 = 0, c21 = 0, c22 = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = points(i, 0) - out.centroid[0], y = points(i, 1) - out.centroid[1],
                 z = points(i, 2) - out.centroid[2];
    const double wx = w(i) * x, wy = w(i) * y, wz = w(i) * z;
    c00 += wx * x;
    c10 += wy * x;
    c20 += wz * x;
    c11 += wy * y;
    c21 += wz * y;
    c22 += wz * z;
  }
  Eigen::Matrix3d C;
  C << c00, 0, 0, c10, c11, 0, c20, c21, c22;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C / sum_w);
  out.eigenvalues = eig.eigenvalues();
  out.axes = eig.eigenvectors();
  out.ok = out.eigenvalues.allFinite() && out.axes.allFinite();
  return out;
}

} // namespace

WeightedPca weighted_pca(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  if (weights.size())
    return pca_of(points, [&](Eigen::Index i) { return weights[i]; });
  return pca_of(points, [](Eigen::Index) { return 1.0; });
}

} // namespace primitive_edit
