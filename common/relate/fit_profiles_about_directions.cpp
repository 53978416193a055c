#include "common/relate/fit_profiles_about_directions.h"

#include "common/base/constants.h"
#include "common/base/parallel_for.h"
#include "common/fit/capped_rms.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/fit_profile_about_direction.h"
#include "common/fit/score_own_fit.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/sagitta.h"
#include "common/relate/relation.h"

#include <algorithm>
#include <cmath>

namespace primitive_edit {

namespace {

// Whether a torus about a direction is a round of the part. A spindle torus (its tube through its axis) is a short
// band's noise floor; one whose tube's centre circle sags less than the cap over the points is the cylinder along
// that circle (a torus of huge major radius, as fit_primitive_auto.h refuses), which does not turn about the
// direction.
bool is_round_about(const Primitive& torus, const FitSample& s, double cap)
{
  if (!(torus.radius > torus.minor_radius))
    return false;
  const Eigen::Vector3d u = any_orthogonal(torus.axis), v = torus.axis.cross(u);
  Eigen::MatrixX2d across(s.points.rows(), 2);
  across.col(0) = s.points * u;
  across.col(1) = s.points * v;
  const double chord = (across.colwise().maxCoeff() - across.colwise().minCoeff()).norm();
  return sagitta(torus.radius, chord) > cap;
}

// Segment s's best primitive about one of the directions, if it beats its own (see Method).
std::optional<SegmentProfile> best_about_directions(int s, const Primitive& mine, const SegmentSamples& samples,
                                                    double roughness, double tolerance,
                                                    const std::vector<PartDirection>& directions,
                                                    const std::optional<PrimitiveType>& asked)
{
  const std::optional<OwnFitScore> own = score_own_fit(samples, mine, kProfilePoints, roughness, tolerance);
  if (!own)
    return std::nullopt;
  const FitSample few = fit_subsample(own->sample.points, Eigen::MatrixX3d(), own->sample.weights, kDirectionPoints);
  double best_score = own->score;
  std::optional<SegmentProfile> best;
  for (const PartDirection& d : directions) {
    for (PrimitiveType type :
         {PrimitiveType::Plane, PrimitiveType::Cylinder, PrimitiveType::Cone, PrimitiveType::Torus}) {
      if (asked && *asked != type)
        continue;
      const std::optional<Primitive> placed = fit_profile_about_direction(few.points, few.weights, d.direction, type);
      if (!placed)
        continue;
      // The axis placed on the few, the profile fitted about it on all the samples.
      const std::optional<Primitive> q =
          type == PrimitiveType::Plane
              ? fit_profile_about_direction(own->sample.points, own->sample.weights, d.direction, type)
              : fit_profile_about_axis(own->sample.points, own->sample.weights, placed->origin, placed->axis, type);
      if (!q || (q->type == PrimitiveType::Torus && !is_round_about(*q, own->sample, own->cap)))
        continue;
      const double rms = capped_rms_to(own->sample, own->cap, *q);
      if (!(rms <= std::min(own->cap, kProfileRmsRatio * own->rms)))
        continue;
      const double score = type_score(rms, direction_degrees_of_freedom(type), own->diagonal);
      if (score < best_score) {
        best_score = score;
        best = SegmentProfile{s, d.segment, rms, *q};
      }
    }
  }
  return best;
}

} // namespace

std::vector<PartDirection> part_directions(const std::vector<std::optional<Primitive>>& primitives,
                                           const std::vector<double>& area, double angle_deg)
{
  std::vector<int> planes;
  double total = 0;
  for (std::size_t s = 0; s < std::min(primitives.size(), area.size()); ++s) {
    if (!primitives[s] || !(area[s] > 0) || !std::isfinite(area[s]))
      continue;
    total += area[s];
    if (primitives[s]->type == PrimitiveType::Plane && primitive_is_valid(*primitives[s]))
      planes.push_back(int(s));
  }
  std::vector<PartDirection> out;
  if (!(angle_deg >= 0 && angle_deg < 90))
    return out;
  std::stable_sort(planes.begin(), planes.end(),
                   [&](int a, int b) { return area[std::size_t(a)] > area[std::size_t(b)]; });
  const double cos_angle = std::cos(radians_from_degrees(angle_deg));
  std::vector<PartDirection> classes;
  std::vector<double> class_area;
  for (int s : planes) {
    const Eigen::Vector3d& normal = primitives[std::size_t(s)]->axis;
    std::size_t k = 0;
    while (k < classes.size() && !(std::abs(classes[k].direction.dot(normal)) >= cos_angle))
      ++k;
    if (k == classes.size()) {
      classes.push_back(PartDirection{s, normal});
      class_area.push_back(0.0);
    }
    class_area[k] += area[std::size_t(s)];
  }
  for (std::size_t k = 0; k < classes.size(); ++k)
    if (class_area[k] >= kPartDirectionShare * total)
      out.push_back(classes[k]);
  return out;
}

std::vector<SegmentProfile> fit_profiles_about_directions(const std::vector<std::optional<Primitive>>& primitives,
                                                          const std::vector<SegmentSamples>& samples,
                                                          double roughness, double tolerance,
                                                          const std::vector<PartDirection>& directions,
                                                          double angle_deg,
                                                          const std::vector<std::optional<PrimitiveType>>& types,
                                                          int threads)
{
  if (!(angle_deg >= 0 && angle_deg < 90) || directions.empty())
    return {};
  const double cos_angle = std::cos(radians_from_degrees(angle_deg));
  // The directions an axis may follow: the planes' and, of two square to each other, the third of their frame (the
  // bracket's long fillets run along the one direction that no large plane faces).
  std::vector<Eigen::Vector3d> followed;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    followed.push_back(directions[i].direction);
    for (std::size_t j = 0; j < i; ++j)
      if (std::abs(directions[i].direction.dot(directions[j].direction)) <= std::sin(radians_from_degrees(angle_deg)))
        followed.push_back(directions[i].direction.cross(directions[j].direction).normalized());
  }
  const auto follows = [&](const Primitive& p) {
    return std::any_of(followed.begin(), followed.end(),
                       [&](const Eigen::Vector3d& d) { return std::abs(d.dot(p.axis)) >= cos_angle; });
  };
  // The candidates: an axis off every direction (one along a direction follows it already: the joint refit holds
  // it there), no type asked that has no direction.
  std::vector<int> candidates;
  std::vector<std::size_t> sizes;
  for (std::size_t s = 0; s < std::min(primitives.size(), samples.size()); ++s) {
    const std::optional<Primitive>& p = primitives[s];
    const bool typed = s < types.size() && types[s].has_value();
    const PrimitiveType asked = typed ? *types[s] : PrimitiveType::Cylinder;
    if (!p || !has_axis(*p) || !primitive_is_valid(*p) || follows(*p) ||
        (typed && (asked == PrimitiveType::Plane || asked == PrimitiveType::Sphere)))
      continue;
    candidates.push_back(int(s));
    sizes.push_back(std::size_t(samples[s].points.rows()));
  }
  std::vector<std::optional<SegmentProfile>> found(candidates.size());
  for_each_largest_first(sizes, std::max(1, std::min(resolve_thread_count(threads), int(candidates.size()))),
                         [&](int, std::size_t i) {
                           const std::size_t s = std::size_t(candidates[i]);
                           found[i] = best_about_directions(int(s), *primitives[s], samples[s], roughness, tolerance,
                                                            directions, s < types.size() ? types[s] : std::nullopt);
                         });
  std::vector<SegmentProfile> out;
  for (const std::optional<SegmentProfile>& q : found)
    if (q)
      out.push_back(*q);
  return out;
}

} // namespace primitive_edit
