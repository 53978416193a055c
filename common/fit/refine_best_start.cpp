#include "common/fit/refine_best_start.h"

namespace primitive_edit {

FitResult refine_best_start(const std::vector<Primitive>& starts, const Eigen::MatrixX3d& points,
                            const Eigen::VectorXd& weights, const FitSample& sample,
                            const FitOptions& options)
{
  // Screening: a few plain (not reweighted) iterations of each start on at most 500 points, judged by the
  // median distance, which outliers do not sway; only the winner gets the robust rounds.
  const FitSample screen = fit_subsample(sample.points, Eigen::MatrixX3d(), sample.weights, 500);
  FitOptions screen_options = options;
  screen_options.max_iterations = std::min(options.max_iterations, 10);
  screen_options.robust = false;
  Primitive winner;
  bool have_winner = false;
  double best_score = std::numeric_limits<double>::infinity();
  for (const Primitive& start : starts) {
    if (!primitive_is_valid(start))
      continue;
    const FitResult r = refine_primitive(start, screen.points, screen.weights, screen_options);
    if (!r.status.ok())
      continue;
    double score = r.rms;
    if (options.robust) {
      std::vector<double> d;
      d.reserve(static_cast<size_t>(screen.points.rows()));
      for (Eigen::Index i = 0; i < screen.points.rows(); ++i)
        if (!screen.weights.size() || screen.weights[i] > 0)
          d.push_back(std::abs(signed_distance_to_primitive(r.primitive, screen.points.row(i).transpose())));
      score = refine_detail::median_abs(d);
    }
    if (score < best_score) {
      best_score = score;
      winner = r.primitive;
      have_winner = true;
    }
  }
  FitResult best;
  best.status = Status::failure("no usable start (degenerate data)");
  if (!have_winner)
    return best;
  best = refine_primitive(winner, sample.points, sample.weights, options);
  if (best.status.ok() && sample.points.rows() < points.rows()) {
    FitResult full = refine_primitive(best.primitive, points, weights, options, 2);
    if (full.status.ok())
      return full;
  }
  return best;
}

} // namespace primitive_edit
