#include "common/relate/relate_primitives.h"

namespace primitive_edit {

namespace relate_detail {

RelatedSegment related_segment(const Primitive& p, const SegmentSamples& s, Eigen::Index count)
{
  RelatedSegment out;
  out.primitive = p;
  const Eigen::Index n = s.points.rows();
  const Eigen::Index m = std::min(n, count);
  out.points.resize(m, 3);
  Eigen::VectorXd w(m);
  const Eigen::VectorXd all = s.weights.size() == n ? s.weights : Eigen::VectorXd::Ones(n);
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::Index j = m == n ? i : (i * n) / m;
    out.points.row(i) = s.points.row(j);
    w[i] = all[j];
  }
  if (w.sum() > 0)
    w *= all.sum() / w.sum();
  double extent = 0;
  if (m > 0)
    extent = (out.points.colwise().maxCoeff() - out.points.colwise().minCoeff()).norm();
  out.weights = refine_detail::tukey_weights(p, out.points, w, 1.0, 1e-9 * std::max(extent, 1e-300));
  return out;
}

int worst_segment(const RelationRefit& refit, const std::vector<FitInformation>& own,
                  const std::vector<const Primitive*>& related, double max_cost_increase, double length)
{
  int worst = -1;
  double worst_ratio = 1.0;
  for (std::size_t s = 0; s < related.size(); ++s) {
    if (!related[s])
      continue;
    const double after = refit.rms[s] * refit.rms[s] * own[s].weight;
    const double allowed = checked_cost_factor(max_cost_increase) * own[s].cost + round_off_cost(length, own[s].weight);
    if (after > allowed && after / allowed > worst_ratio) {
      worst = int(s);
      worst_ratio = after / allowed;
    }
  }
  return worst;
}

int drop_relations_of(int worst, std::vector<Relation>& kept, std::vector<char>& is_position)
{
  auto involves = [&](std::size_t r) { return worst < 0 || kept[r].a == worst || kept[r].b == worst; };
  bool any_position = false;
  for (std::size_t r = 0; r < kept.size(); ++r)
    any_position = any_position || (is_position[r] && involves(r));
  std::vector<Relation> next;
  std::vector<char> next_is_position;
  for (std::size_t r = 0; r < kept.size(); ++r)
    if (!involves(r) || (any_position && !is_position[r])) {
      next.push_back(kept[r]);
      next_is_position.push_back(is_position[r]);
    }
  const int dropped = int(kept.size() - next.size());
  kept.swap(next);
  is_position.swap(next_is_position);
  return dropped;
}

} // namespace relate_detail

RelatedPrimitives relate_primitives(const std::vector<std::optional<Primitive>>& fitted,
                                    const std::vector<SegmentSamples>& samples,
                                    const std::vector<SegmentContact>& contacts, double noise,
                                    const RelationOptions& options, const std::vector<char>& fixed,
                                    int threads)
{
  using namespace relate_detail;
  RelatedPrimitives out;
  out.primitives = fitted;
  if (!(options.angle_deg > 0 && options.angle_deg < 90) || !std::isfinite(options.distance) ||
      !(options.max_cost_increase > 0) || !std::isfinite(options.max_cost_increase)) {
    out.status = Status::failure("the relation angle must be between 0 and 90 degrees, the distance finite and the "
                                 "cost share positive");
    return out;
  }
  const int count = int(std::min(fitted.size(), samples.size()));
  std::vector<RelatedSegment> segments(static_cast<std::size_t>(count));
  std::vector<const Primitive*> start(std::size_t(count), nullptr);
  for (int s = 0; s < count; ++s) {
    const std::optional<Primitive>& p = fitted[std::size_t(s)];
    if (!p || !primitive_is_valid(*p) || samples[std::size_t(s)].points.rows() == 0)
      continue;
    // A sample at infinity would stretch the part's size and the segment's fit without bound (one rule for
    // every fit's input: check_fit_input.h). out.primitives is still the input.
    const SegmentSamples& ss = samples[std::size_t(s)];
    const Status input = check_fit_input(ss.points, Eigen::MatrixX3d(), ss.weights, 0);
    if (!input) {
      out.status = Status::failure("segment " + std::to_string(s) + "'s samples: " + input.error);
      return out;
    }
    segments[std::size_t(s)] = related_segment(*p, samples[std::size_t(s)], kRelateSamples);
    segments[std::size_t(s)].fixed = std::size_t(s) < fixed.size() && fixed[std::size_t(s)];
    if (segments[std::size_t(s)].weights.sum() > 0)
      start[std::size_t(s)] = &segments[std::size_t(s)].primitive;
  }
  const double length = part_size(segments);
  out.length = length;
  // Each segment's residuals in units of its own noise (maximum likelihood with a noise per segment): in the
  // joint refit an exact face stays and a rough one follows. The checks compare each segment's cost with its
  // own, so they do not change.
  for (int s = 0; s < count; ++s)
    if (start[std::size_t(s)]) {
      RelatedSegment& r = segments[std::size_t(s)];
      const double rms = fit_residuals(r.primitive, r.points, r.weights).rms;
      r.weights /= rms * rms + round_off_cost(length, 1.0);
    }
  out.distance = options.distance > 0 ? options.distance : is_known_scale(noise) ? 3.0 * noise : 0.01 * length;
  const double angle = radians_from_degrees(options.angle_deg);

  auto information = [&](const std::vector<const Primitive*>& p) {
    std::vector<FitInformation> info(static_cast<std::size_t>(count));
    for (int s = 0; s < count; ++s)
      if (p[std::size_t(s)])
        info[std::size_t(s)] = fit_information(*p[std::size_t(s)], segments[std::size_t(s)].points,
                                               segments[std::size_t(s)].weights);
    return info;
  };
  const std::vector<FitInformation> info0 = information(start);

  // 1. Directions.
  std::vector<Relation> directions = detect_direction_relations(start, info0, angle, options.max_cost_increase, length);
  RelationRefit first = refit_with_relations(segments, directions, kRelationRefitIterations, threads);
  if (!first.status)
    directions.clear(), first = refit_with_relations(segments, directions, kRelationRefitIterations, threads);
  // 2. Positions, among the primitives refitted under the directions.
  std::vector<const Primitive*> turned(std::size_t(count), nullptr);
  for (int s = 0; s < count; ++s)
    if (start[std::size_t(s)])
      turned[std::size_t(s)] = &first.primitives[std::size_t(s)];
  const std::vector<Relation> positions = detect_position_relations(
      turned, information(turned), contacts, angle, out.distance, options.max_cost_increase, length);

  // 3. Refit with all, and check every segment against its own fit; drop what breaks a segment.
  std::vector<Relation> kept = directions;
  const std::size_t first_position = kept.size();
  kept.insert(kept.end(), positions.begin(), positions.end());
  std::vector<char> is_position(kept.size(), 0);
  std::fill(is_position.begin() + std::ptrdiff_t(first_position), is_position.end(), 1);
  RelationRefit refit;
  for (int round = 0;; ++round) {
    std::vector<RelatedSegment> from = segments;
    for (int s = 0; s < count; ++s)
      from[std::size_t(s)].primitive = first.primitives[std::size_t(s)];
    refit = refit_with_relations(round == 0 ? from : segments, kept, kRelationRefitIterations, threads);
    const int worst = refit.status ? worst_segment(refit, info0, start, options.max_cost_increase, length) : -1;
    if ((refit.status && worst < 0) || kept.empty() || round == 8)
      break;
    out.dropped += drop_relations_of(worst, kept, is_position);
  }
  if (!refit.status) {
    out.dropped += int(kept.size());
    kept.clear();
    refit = refit_with_relations(segments, kept, kRelationRefitIterations, threads);
  }
  out.relations = kept;
  for (int s = 0; s < count; ++s)
    if (start[std::size_t(s)])
      out.primitives[std::size_t(s)] = refit.primitives[std::size_t(s)];
  return out;
}

} // namespace primitive_edit
