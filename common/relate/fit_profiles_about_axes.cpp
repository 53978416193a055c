#include "common/relate/fit_profiles_about_axes.h"

#include "common/base/constants.h"
#include "common/fit/capped_rms.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/fit_profile_about_axis.h"
#include "common/fit/score_own_fit.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/meridian_section.h"
#include "common/geometry/sagitta.h"

#include <algorithm>
#include <cmath>

namespace primitive_edit {

namespace {

bool is_revolution(PrimitiveType t)
{
  return t == PrimitiveType::Sphere || t == PrimitiveType::Cone || t == PrimitiveType::Torus;
}

// Whether p turns about the cylinder c's axis: a sphere's centre, or the point of a cone's or torus's axis
// nearest to the segment's centroid (a cone's apex can lie far beyond its data), within `distance` of the axis,
// and the axes within the angle.
bool turns_about(const Primitive& p, const Primitive& c, const Eigen::Vector3d& centroid, double cos_angle,
                 double distance)
{
  Eigen::Vector3d on_own_axis = p.origin;
  if (p.type != PrimitiveType::Sphere) {
    if (!(std::abs(p.axis.dot(c.axis)) >= cos_angle))
      return false;
    on_own_axis += (centroid - p.origin).dot(p.axis) * p.axis;
  }
  const Eigen::Vector3d d = on_own_axis - c.origin;
  return (d - d.dot(c.axis) * c.axis).norm() <= distance;
}

// The primitive of `type` about c's axis that fits the samples, refitted once without the samples beyond the cap.
std::optional<Primitive> profile_about(const FitSample& s, const Primitive& c, PrimitiveType type, double cap)
{
  std::optional<Primitive> q = fit_profile_about_axis(s.points, s.weights, c.origin, c.axis, type);
  if (!q)
    return q;
  Eigen::VectorXd near = s.weights;
  for (Eigen::Index i = 0; i < near.size(); ++i)
    if (!(std::abs(project_onto_primitive(*q, s.points.row(i).transpose()).signed_distance) <= cap))
      near[i] = 0;
  if (std::optional<Primitive> again = fit_profile_about_axis(s.points, near, c.origin, c.axis, type))
    q = again;
  return q;
}

} // namespace

std::vector<SegmentProfile> fit_profiles_about_axes(const std::vector<std::optional<Primitive>>& primitives,
                                                    const std::vector<SegmentSamples>& samples, double roughness,
                                                    double tolerance, double angle_deg, double distance,
                                                    const std::vector<std::optional<PrimitiveType>>& types)
{
  std::vector<SegmentProfile> out;
  const int count = int(std::min(primitives.size(), samples.size()));
  if (!(angle_deg >= 0 && angle_deg < 90) || !(distance > 0) || !std::isfinite(distance))
    return out;
  const double cos_angle = std::cos(radians_from_degrees(angle_deg));
  std::vector<int> axes;
  for (int s = 0; s < count; ++s) {
    const std::optional<Primitive>& p = primitives[std::size_t(s)];
    if (p && p->type == PrimitiveType::Cylinder && primitive_is_valid(*p))
      axes.push_back(s);
  }
  for (int s = 0; s < count && !axes.empty(); ++s) {
    const std::optional<Primitive>& mine = primitives[std::size_t(s)];
    const bool typed = std::size_t(s) < types.size() && types[std::size_t(s)].has_value();
    const PrimitiveType asked = typed ? *types[std::size_t(s)] : mine ? mine->type : PrimitiveType::Plane;
    if (!mine || !is_revolution(mine->type) || !primitive_is_valid(*mine) || !is_revolution(asked))
      continue;
    const std::optional<OwnFitScore> own =
        score_own_fit(samples[std::size_t(s)], mine, kProfilePoints, roughness, tolerance);
    if (!own)
      continue;
    const FitSample& sample = own->sample;
    const Eigen::Vector3d centroid =
        (sample.weights.transpose() * sample.points).transpose() / sample.weights.sum();
    double best_score = own->score;
    std::optional<SegmentProfile> best;
    for (int a : axes) {
      const Primitive& c = *primitives[std::size_t(a)];
      if (a == s || !turns_about(*mine, c, centroid, cos_angle, distance))
        continue;
      const std::optional<MeridianFrame> frame = meridian_frame(c.origin, c.axis, centroid);
      const double chord = frame ? meridian_extent(*frame, sample.points, sample.weights) : 0.0;
      for (PrimitiveType type : {PrimitiveType::Cone, PrimitiveType::Sphere, PrimitiveType::Torus}) {
        if (typed && asked != type)
          continue;
        const std::optional<Primitive> q = profile_about(sample, c, type, own->cap);
        if (!q)
          continue;
        // A sphere whose meridian arc sags less than the tolerance over the band is the cone of its chord, as a free
        // fit's sphere that sags less is a plane (fit_primitive_auto.h).
        if (!typed && type == PrimitiveType::Sphere && !(sagitta(q->radius, chord) > own->cap))
          continue;
        const double rms = capped_rms_to(sample, own->cap, *q);
        if (!(rms <= std::min(own->cap, kProfileRmsRatio * own->rms)))
          continue;
        const double score = type_score(rms, profile_degrees_of_freedom(type), own->diagonal);
        if (score < best_score) {
          best_score = score;
          best = SegmentProfile{s, a, rms, *q};
        }
      }
    }
    if (best)
      out.push_back(*best);
  }
  return out;
}

} // namespace primitive_edit
