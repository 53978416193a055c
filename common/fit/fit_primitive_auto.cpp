#include "common/fit/fit_primitive_auto.h"

#include "common/base/parallel_for.h"
#include "common/geometry/sagitta.h"

#include <atomic>

namespace primitive_edit {

namespace fit_auto_detail {

std::vector<FitResult> screen_candidates(const FitSample& s, const FitOptions& options, int threads)
{
  std::vector<FitResult> candidates(kPrimitiveTypeCount);
  // Costliest first, so that two threads finish together (300 noisy points of a plane: cone 1.9 ms, torus 1.5,
  // cylinder 0.8, sphere and plane 0.1-0.15).
  static constexpr PrimitiveType order[kPrimitiveTypeCount] = {PrimitiveType::Cone, PrimitiveType::Torus,
                                                               PrimitiveType::Cylinder, PrimitiveType::Sphere,
                                                               PrimitiveType::Plane};
  std::atomic<int> next{0};
  parallel_for(std::size_t(kPrimitiveTypeCount), threads, 1, [&](std::size_t, std::size_t) {
    for (int i = next++; i < kPrimitiveTypeCount; i = next++) {
      const PrimitiveType type = order[i];
      candidates[std::size_t(type)] = fit_primitive(type, s.points, s.normals, s.weights, options);
    }
  });
  return candidates;
}

} // namespace fit_auto_detail

AutoFitResult fit_primitive_auto(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                                 const Eigen::VectorXd& weights, const AutoFitOptions& options)
{
  AutoFitResult out;
  out.status = check_fit_input(points, normals, weights, minimum_points_for(PrimitiveType::Plane));
  if (!out.status)
    return out;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (!weights.size() || weights[i] > 0) {
      lo = lo.cwiseMin(points.row(i).transpose());
      hi = hi.cwiseMax(points.row(i).transpose());
    }
  const double diagonal = (hi - lo).norm();
  if (!(diagonal > 0)) {
    out.status = Status::failure("all points coincide");
    return out;
  }
  // A rough scan's segments deviate from their primitive by its roughness whatever their size.
  const double tolerance =
      options.tolerance > 0 ? options.tolerance : automatic_fit_tolerance(diagonal, options.roughness);
  const FitSample s = fit_subsample(points, normals, weights, kAutoFitScreenPoints);
  FitOptions screen_options = options.fit;
  screen_options.max_iterations = std::min(screen_options.max_iterations, 20);

  int chosen = -1;
  double chosen_score = std::numeric_limits<double>::infinity();
  int fallback = -1;
  double fallback_score = std::numeric_limits<double>::infinity();
  out.candidates = fit_auto_detail::screen_candidates(s, screen_options, options.threads);
  for (int t = 0; t < kPrimitiveTypeCount; ++t) {
    const PrimitiveType type = static_cast<PrimitiveType>(t);
    const FitResult& c = out.candidates[std::size_t(t)];
    if (!c.status.ok())
      continue;
    const double score = type_score(c.rms, primitive_degrees_of_freedom(type), diagonal);
    const Primitive& p = c.primitive;
    bool eligible = c.rms <= tolerance;
    if (type == PrimitiveType::Sphere || type == PrimitiveType::Cylinder)
      eligible = eligible && sagitta(p.radius, diagonal) > tolerance;
    if (type == PrimitiveType::Cone)
      eligible = eligible && !cone_is_cylinder_within(p, s.points, s.weights, tolerance);
    if (type == PrimitiveType::Torus)
      eligible = eligible && p.radius < 100 * diagonal;
    if (eligible && score < chosen_score) {
      chosen = t;
      chosen_score = score;
    }
    if (score < fallback_score) {
      fallback = t;
      fallback_score = score;
    }
  }
  if (chosen < 0) {
    out.status = Status::failure(fallback < 0 ? "no primitive type could be fitted"
                                 : "free-form: no primitive fits within the tolerance " + std::to_string(tolerance));
    if (fallback >= 0)
      out.best = out.candidates[static_cast<size_t>(fallback)];
    return out;
  }
  // The screen may have stopped early or seen a subsample: the winner gets the full refinement.
  FitResult& winner = out.candidates[static_cast<size_t>(chosen)];
  FitResult full = refine_primitive(winner.primitive, points, weights, options.fit, 2);
  if (full.status.ok())
    winner = full;
  out.best = winner;
  if (!(winner.rms <= tolerance))
    out.status = Status::failure("free-form: the chosen " + std::string(primitive_type_name(winner.primitive.type)) +
                                 " exceeds the tolerance on all points");
  return out;
}

} // namespace primitive_edit
