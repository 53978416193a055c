#include "common/fit/score_own_fit.h"

#include "common/fit/capped_rms.h"
#include "common/fit/check_fit_input.h"
#include "common/fit/fit_primitive_auto.h"

#include <cmath>
#include <limits>

namespace primitive_edit {

std::optional<OwnFitScore> score_own_fit(const SegmentSamples& own, const std::optional<Primitive>& primitive,
                                         Eigen::Index max_points, double roughness, double tolerance)
{
  if (own.weights.size() != own.points.rows() ||
      !check_fit_input(own.points, Eigen::MatrixX3d(), own.weights, 1).ok())
    return std::nullopt;
  OwnFitScore out;
  out.sample = fit_subsample(own.points, Eigen::MatrixX3d(), own.weights, max_points);
  out.diagonal = (out.sample.points.colwise().maxCoeff() - out.sample.points.colwise().minCoeff()).norm();
  out.cap = tolerance > 0 ? tolerance : automatic_fit_tolerance(out.diagonal, roughness);
  if (!(out.cap > 0) || !std::isfinite(out.cap) || !(out.sample.weights.sum() > 0))
    return std::nullopt;
  out.rms = out.cap;
  out.score = std::numeric_limits<double>::infinity();
  if (primitive) {
    out.rms = capped_rms_to(out.sample, out.cap, *primitive);
    out.score = type_score(out.rms, primitive_degrees_of_freedom(primitive->type), out.diagonal);
  }
  return out;
}

} // namespace primitive_edit
