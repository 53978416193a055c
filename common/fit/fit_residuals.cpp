#include "common/fit/fit_residuals.h"

namespace primitive_edit {

FitResult fit_residuals(const Primitive& prim, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
{
  FitResult out;
  out.primitive = prim;
  if (!primitive_is_valid(prim)) {
    out.status = Status::failure("invalid primitive");
    return out;
  }
  double sum_wd2 = 0, sum_w = 0, max_d = 0;
  int count = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const double w = weights.size() ? weights[i] : 1.0;
    if (!(w > 0))
      continue;
    const double d = std::abs(signed_distance_to_primitive(prim, points.row(i).transpose()));
    sum_wd2 += w * d * d;
    sum_w += w;
    max_d = std::max(max_d, d);
    ++count;
  }
  if (count == 0 || !(sum_w > 0)) {
    out.status = Status::failure("no point with positive weight");
    return out;
  }
  out.rms = std::sqrt(sum_wd2 / sum_w);
  out.max_residual = max_d;
  out.point_count = count;
  return out;
}

} // namespace primitive_edit
