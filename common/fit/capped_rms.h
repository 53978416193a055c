// capped_rms.h: the RMS of distances each capped at a tolerance, to compare candidate surfaces on one segment.
//
// Input:  samples (fit_subsample.h: points and weights), the cap (> 0) and a distance function of a point, or
//         a primitive (capped_rms_to: the distance is |signed distance| to it, closest_point_on_primitive.h).
// Output: sqrt(sum(w * min(d, cap)^2) / sum(w)); infinity when no weight is positive. A point farther than the
//         cap (another face's, an outlier) counts as the cap, whatever surface is scored, so it cannot decide
//         between them.
// Cost:   O(N) distances.
#ifndef PRIMITIVE_EDIT_CAPPED_RMS_H
#define PRIMITIVE_EDIT_CAPPED_RMS_H

#include "common/fit/fit_subsample.h"
#include "common/geometry/closest_point_on_primitive.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace primitive_edit {

template <class Distance>
double capped_rms(const FitSample& s, double cap, Distance distance)
{
  double sum = 0, weight = 0;
  for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
    const double d = std::min(distance(Eigen::Vector3d(s.points.row(i).transpose())), cap);
    sum += s.weights[i] * d * d;
    weight += s.weights[i];
  }
  return weight > 0 ? std::sqrt(sum / weight) : std::numeric_limits<double>::infinity();
}

inline double capped_rms_to(const FitSample& s, double cap, const Primitive& primitive)
{
  return capped_rms(s, cap, [&](const Eigen::Vector3d& p) {
    return std::abs(project_onto_primitive(primitive, p).signed_distance);
  });
}

} // namespace primitive_edit

#endif
