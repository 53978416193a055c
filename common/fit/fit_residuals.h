// fit_residuals.h: the RMS and maximum orthogonal distance of points to a primitive.
//
// Input:  a primitive, points N x 3, weights N (empty = all 1). Points of zero weight are ignored.
// Output: a FitResult with the primitive, rms = sqrt(sum w d^2 / sum w) (weights as given, e.g. areas),
//         max_residual = max |d|, point_count = number of points with w > 0, and ok = the primitive is
//         valid and at least one point counted.
// Cost:   O(N).
#ifndef PRIMITIVE_EDIT_FIT_RESIDUALS_H
#define PRIMITIVE_EDIT_FIT_RESIDUALS_H

#include "common/geometry/closest_point_on_primitive.h"
#include "common/fit/fit_result.h"

#include <algorithm>
#include <cmath>

namespace primitive_edit {

inline FitResult fit_residuals(const Primitive& prim, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights)
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

#endif
