#include "common/relate/fit_edge_blends.h"

#include "common/base/constants.h"
#include "common/fit/capped_rms.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/score_own_fit.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/edge_blend_likelihood.h"
#include "common/geometry/edge_blend_window.h"
#include "common/geometry/meridian_section.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace primitive_edit {

namespace {

// Whether a segment asked `type` may be a blend of that form: two planes' fillet is a cylinder and their chamfer a
// plane; about an axis, a torus and a cone.
bool form_allowed(const std::optional<PrimitiveType>& type, BlendForm form, bool about_axis)
{
  if (!type)
    return true;
  if (form == BlendForm::Fillet)
    return *type == (about_axis ? PrimitiveType::Torus : PrimitiveType::Cylinder);
  return *type == (about_axis ? PrimitiveType::Cone : PrimitiveType::Plane);
}

// The blend of segment s between planes a and b whose borders with it (their means ma and mb) agree, or
// std::nullopt. About an axis, everything is given in the meridian space.
std::optional<SegmentEdgeBlend> blend_between(int s, int a, int b, const Primitive& pa, const Primitive& pb,
                                              const Eigen::Vector3d& ma, const Eigen::Vector3d& mb,
                                              const FitSample& samples, double cap,
                                              const std::optional<PrimitiveType>& type, bool about_axis,
                                              bool given = false)
{
  // Each border lies on its plane's kept half, beyond the edge as seen from the other border.
  const std::optional<EdgeSection> section = edge_section(pa, pb, 2 * ma - mb, 2 * mb - ma, 0.5 * (ma + mb));
  if (!section)
    return std::nullopt;
  const double ta = distance_along(*section, section->ray_a, ma);
  const double tb = distance_along(*section, section->ray_b, mb);
  const double setback = 0.5 * (ta + tb);
  if (!(ta > 0 && tb > 0) || !(given || std::abs(ta - tb) <= std::max(cap, kEdgeBlendBorderShare * setback)))
    return std::nullopt;
  std::optional<SegmentEdgeBlend> best;
  for (BlendForm form : {BlendForm::Fillet, BlendForm::Chamfer}) {
    if (!form_allowed(type, form, about_axis))
      continue;
    const double rms = capped_rms(samples, cap, [&](const Eigen::Vector3d& p) {
      return edge_blend_distance(*section, form, setback, p);
    });
    if (!best || rms < best->rms)
      best = SegmentEdgeBlend{s, a, b, *section, form, setback, rms, edge_blend_primitive(*section, form, setback)};
  }
  if (!best)
    return std::nullopt;
  best->contact_a = section->origin + setback * section->ray_a;
  best->contact_b = section->origin + setback * section->ray_b;
  double inside = 0, all = 0;
  for (Eigen::Index i = 0; i < samples.points.rows(); ++i) {
    all += samples.weights[i];
    if (in_edge_blend_sector(*section, setback, samples.points.row(i).transpose()))
      inside += samples.weights[i];
  }
  if (!(inside >= (given ? kGivenEdgeBlendSectorShare : kEdgeBlendSectorShare) * all) ||
      !primitive_is_valid(best->primitive))
    return std::nullopt;
  return best;
}

// How much likelier the blend makes the samples of its segment and of its planes about their edge than the sharp
// edge does, as the segmentation's carve measures it (edge_blend_window.h: the planes' samples beyond the
// largest setback give the scatter): a blend standing off its edge by less than the roughness shows here, not in
// its RMS. 0 when there is no such window. `map` takes a sample into the blend's space (about an axis: the
// meridian's).
template <class Map>
double blend_gain(const SegmentEdgeBlend& blend, const SegmentSamples& own, const SegmentSamples& a,
                  const SegmentSamples& b, const Primitive& pa, const Primitive& pb, double tolerance, const Map& map)
{
  const EdgeSection& section = blend.section;
  EdgeBlendWindow window(section, tolerance);
  if (!(tolerance > 0) || !(blend.setback < window.max_setback()) || own.points.rows() == 0)
    return 0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (Eigen::Index i = 0; i < own.points.rows(); ++i) {
    const Eigen::Vector3d p = map(own.points.row(i).transpose());
    const double t = (p - section.origin).dot(section.direction);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
    window.add(p, own.weights[i]);
  }
  auto take_plane = [&](const SegmentSamples& s, const Eigen::Vector3d& ray, const Primitive& plane) {
    for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
      const Eigen::Vector3d p = map(s.points.row(i).transpose());
      const double t = (p - section.origin).dot(section.direction);
      if (t >= lo && t <= hi && in_section(section, p).norm() <= std::sqrt(2.0) * window.reach())
        window.add_on_plane(p, s.weights[i], ray, plane);
    }
  };
  take_plane(a, section.ray_a, pa);
  take_plane(b, section.ray_b, pb);
  const std::optional<EdgeBlendSample> sample = window.sample();
  if (!sample)
    return 0;
  const double sharp =
      edge_blend_cost(section, sample->points, sample->weights, sample->spread, window.reach(), blend.form, 0.0);
  const double rounded = edge_blend_cost(section, sample->points, sample->weights, sample->spread, window.reach(),
                                         blend.form, blend.setback);
  return (sharp - rounded) * double(sample->points.rows());
}

int other_of(const SegmentContact& c, int s) { return c.a == s ? c.b : c.a; }

// The mean of a border's points in the meridian space (a border about the axis has its mean on the axis).
Eigen::Vector3d meridian_mean(const MeridianFrame& frame, const SegmentContact& c)
{
  if (c.points.empty())
    return to_meridian(frame, c.mean);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : c.points)
    sum += to_meridian(frame, p);
  return sum / double(c.points.size());
}

// A blend about an axis and its two neighbours as the lines of its meridian space, where its gain is measured.
struct MeridianBlend
{
  SegmentEdgeBlend blend;
  Primitive level, line;
};

// Segment s's blend of plane a and the cylinder or cone t turning about a's normal (within axis_angle_deg), made in
// their meridian space and turned back about t's axis; std::nullopt when there is none or it is of a type other
// than the one asked.
std::optional<MeridianBlend> blend_about_axis(int s, const SegmentContact& with_plane,
                                                 const SegmentContact& with_turned,
                                                 const std::vector<std::optional<Primitive>>& primitives,
                                                 const OwnFitScore& own, double axis_angle_deg,
                                                 const std::optional<PrimitiveType>& type)
{
  const int a = other_of(with_plane, s), t = other_of(with_turned, s);
  const Primitive& plane = *primitives[std::size_t(a)];
  const Primitive& turned = *primitives[std::size_t(t)];
  if (!(std::abs(plane.axis.dot(turned.axis)) >= std::cos(radians_from_degrees(axis_angle_deg))))
    return std::nullopt;
  const Eigen::Vector3d middle =
      (own.sample.weights.transpose() * own.sample.points).transpose() / own.sample.weights.sum();
  const std::optional<MeridianFrame> frame = meridian_frame(turned.origin, turned.axis, middle);
  if (!frame)
    return std::nullopt;
  const std::optional<Primitive> level = meridian_of_plane(*frame, plane, with_plane.mean);
  const std::optional<Primitive> line = meridian_of_turned(*frame, turned);
  if (!level || !line)
    return std::nullopt;
  FitSample mapped = own.sample;
  for (Eigen::Index i = 0; i < mapped.points.rows(); ++i)
    mapped.points.row(i) = to_meridian(*frame, own.sample.points.row(i).transpose()).transpose();
  std::optional<SegmentEdgeBlend> blend =
      blend_between(s, a, t, *level, *line, meridian_mean(*frame, with_plane),
                    meridian_mean(*frame, with_turned), mapped, own.cap, type, true);
  if (!blend)
    return std::nullopt;
  const std::optional<Primitive> swept = revolve(*frame, blend->primitive);
  if (!swept || (type && swept->type != *type))
    return std::nullopt;
  blend->primitive = *swept;
  blend->meridian = frame;
  blend->contact_a = from_meridian(*frame, blend->contact_a);
  blend->contact_b = from_meridian(*frame, blend->contact_b);
  return MeridianBlend{*blend, *level, *line};
}

// The best-scoring blend of segment s between any two of the planes it touches, or a plane and a cylinder or cone
// turning about its normal, better than its own primitive. Failing that, the blend its samples and its neighbours'
// make likeliest against the sharp edge, by kMinBlendGain or more (blend_gain): the test the segmentation's carve
// made, for a segmentation that no longer has its records.
std::optional<SegmentEdgeBlend> best_blend_of(int s, const std::vector<std::optional<Primitive>>& primitives,
                                              const std::vector<SegmentSamples>& samples, const OwnFitScore& own,
                                              const std::vector<const SegmentContact*>& planes,
                                              const std::vector<const SegmentContact*>& turned,
                                              double axis_angle_deg, const std::optional<PrimitiveType>& type)
{
  double best_score = own.score, best_gain = kMinBlendGain;
  std::optional<SegmentEdgeBlend> chosen, likeliest;
  // gain(blend): blend_gain in the blend's space, called only while no blend beats the own primitive.
  auto weigh = [&](const std::optional<SegmentEdgeBlend>& blend, const auto& gain) {
    if (!blend)
      return;
    const double score = type_score(blend->rms, 1, own.diagonal);
    if (blend->rms <= std::min(own.cap, kEdgeBlendRmsRatio * own.rms) && score < best_score) {
      best_score = score;
      chosen = blend;
    }
    if (chosen)
      return;
    const double g = gain(*blend);
    if (g >= best_gain) {
      best_gain = g;
      likeliest = blend;
    }
  };
  const SegmentSamples& own_samples = samples[std::size_t(s)];
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const int a = other_of(*planes[i], s);
    const Primitive& pa = *primitives[std::size_t(a)];
    for (std::size_t j = i + 1; j < planes.size(); ++j) {
      const int b = other_of(*planes[j], s);
      const Primitive& pb = *primitives[std::size_t(b)];
      weigh(blend_between(s, a, b, pa, pb, planes[i]->mean, planes[j]->mean, own.sample, own.cap, type, false),
            [&](const SegmentEdgeBlend& blend) {
              return blend_gain(blend, own_samples, samples[std::size_t(a)], samples[std::size_t(b)], pa, pb, own.cap,
                                [](const Eigen::Vector3d& p) { return p; });
            });
    }
    if (!(axis_angle_deg > 0))
      continue;
    for (const SegmentContact* with_turned : turned) {
      const std::optional<MeridianBlend> m =
          blend_about_axis(s, *planes[i], *with_turned, primitives, own, axis_angle_deg, type);
      if (!m)
        continue;
      weigh(m->blend, [&](const SegmentEdgeBlend& blend) {
        const MeridianFrame& frame = *blend.meridian;
        return blend_gain(blend, own_samples, samples[std::size_t(a)], samples[std::size_t(blend.plane_b)], m->level,
                          m->line, own.cap, [&](const Eigen::Vector3d& p) { return to_meridian(frame, p); });
      });
    }
  }
  return chosen ? chosen : likeliest;
}

// The blend the record gives segment r.segment, when it still touches both planes, each border lies on its plane's
// kept half and kGivenEdgeBlendSectorShare of it lies between the tangent lines.
std::optional<SegmentEdgeBlend> given_blend(const SegmentBlendRecord& r,
                                            const std::vector<std::optional<Primitive>>& primitives,
                                            const SegmentSamples& samples,
                                            const std::vector<const SegmentContact*>& touching, double roughness,
                                            double tolerance, const std::optional<PrimitiveType>& type)
{
  const SegmentContact *with_a = nullptr, *with_b = nullptr;
  for (const SegmentContact* c : touching) {
    const int other = other_of(*c, r.segment);
    with_a = other == r.plane_a ? c : with_a;
    with_b = other == r.plane_b ? c : with_b;
  }
  if (!with_a || !with_b)
    return std::nullopt;
  const std::optional<OwnFitScore> own =
      score_own_fit(samples, primitives[std::size_t(r.segment)], kEdgeBlendPoints, roughness, tolerance);
  if (!own)
    return std::nullopt;
  return blend_between(r.segment, r.plane_a, r.plane_b, *primitives[std::size_t(r.plane_a)],
                       *primitives[std::size_t(r.plane_b)], with_a->mean, with_b->mean, own->sample, own->cap, type,
                       false, true);
}

} // namespace

std::vector<SegmentEdgeBlend> fit_edge_blends(const std::vector<std::optional<Primitive>>& primitives,
                                              const std::vector<SegmentSamples>& samples,
                                              const std::vector<SegmentContact>& contacts, double roughness,
                                              double tolerance, const std::vector<std::optional<PrimitiveType>>& types,
                                              const std::vector<SegmentBlendRecord>& given, double axis_angle_deg)
{
  const int count = int(std::min(primitives.size(), samples.size()));
  auto valid_of = [&](int k, std::initializer_list<PrimitiveType> kinds) {
    if (k < 0 || k >= count || !primitives[std::size_t(k)] || !primitive_is_valid(*primitives[std::size_t(k)]))
      return false;
    return std::find(kinds.begin(), kinds.end(), primitives[std::size_t(k)]->type) != kinds.end();
  };
  auto is_plane = [&](int k) { return valid_of(k, {PrimitiveType::Plane}); };
  auto is_turned = [&](int k) { return valid_of(k, {PrimitiveType::Cylinder, PrimitiveType::Cone}); };
  std::vector<std::vector<const SegmentContact*>> planes_of(std::size_t(std::max(count, 0)));
  std::vector<std::vector<const SegmentContact*>> turned_of(std::size_t(std::max(count, 0)));
  for (const SegmentContact& c : contacts) {
    if (c.a < 0 || c.b < 0 || c.a >= count || c.b >= count || c.a == c.b || !c.mean.allFinite() ||
        !std::all_of(c.points.begin(), c.points.end(), [](const Eigen::Vector3d& p) { return p.allFinite(); }))
      continue;
    for (const auto& [s, other] : {std::pair(c.a, c.b), std::pair(c.b, c.a)}) {
      if (is_plane(other))
        planes_of[std::size_t(s)].push_back(&c);
      else if (is_turned(other))
        turned_of[std::size_t(s)].push_back(&c);
    }
  }
  auto type_of = [&](int s) { return std::size_t(s) < types.size() ? types[std::size_t(s)] : std::nullopt; };
  enum Role : char { kNone, kBlend, kBlendsPlane };
  std::vector<char> role(std::size_t(std::max(count, 0)), kNone);
  std::vector<SegmentEdgeBlend> out;
  for (const SegmentBlendRecord& r : given) {
    if (r.segment < 0 || r.segment >= count || !is_plane(r.plane_a) || !is_plane(r.plane_b) ||
        role[std::size_t(r.segment)] != kNone || role[std::size_t(r.plane_a)] == kBlend ||
        role[std::size_t(r.plane_b)] == kBlend)
      continue;
    const std::optional<SegmentEdgeBlend> blend = given_blend(r, primitives, samples[std::size_t(r.segment)],
                                                              planes_of[std::size_t(r.segment)], roughness,
                                                              tolerance, type_of(r.segment));
    if (!blend)
      continue;
    role[std::size_t(r.segment)] = kBlend;
    role[std::size_t(r.plane_a)] = role[std::size_t(r.plane_b)] = kBlendsPlane;
    out.push_back(*blend);
  }
  std::vector<SegmentEdgeBlend> candidates;
  for (int s = 0; s < count; ++s) {
    const std::size_t planes = planes_of[std::size_t(s)].size();
    const bool about_axis = axis_angle_deg > 0 && planes >= 1 && !turned_of[std::size_t(s)].empty();
    if ((planes < 2 && !about_axis) || role[std::size_t(s)] != kNone)
      continue;
    const std::optional<OwnFitScore> own =
        score_own_fit(samples[std::size_t(s)], primitives[std::size_t(s)], kEdgeBlendPoints, roughness, tolerance);
    if (!own)
      continue;
    if (std::optional<SegmentEdgeBlend> blend =
            best_blend_of(s, primitives, samples, *own, planes_of[std::size_t(s)], turned_of[std::size_t(s)],
                          axis_angle_deg, type_of(s)))
      candidates.push_back(*blend);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const SegmentEdgeBlend& x, const SegmentEdgeBlend& y) { return x.setback < y.setback; });
  for (const SegmentEdgeBlend& c : candidates) {
    if (role[std::size_t(c.segment)] != kNone || role[std::size_t(c.plane_a)] == kBlend ||
        role[std::size_t(c.plane_b)] == kBlend)
      continue;
    role[std::size_t(c.segment)] = kBlend;
    role[std::size_t(c.plane_a)] = role[std::size_t(c.plane_b)] = kBlendsPlane;
    out.push_back(c);
  }
  return out;
}

} // namespace primitive_edit
