#include "common/relate/fit_edge_blends.h"

#include "common/fit/capped_rms.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/score_own_fit.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/edge_blend_likelihood.h"
#include "common/geometry/edge_blend_window.h"

#include <algorithm>
#include <cmath>

namespace primitive_edit {

namespace {

// The blend of segment s between planes a and b whose borders with it agree, or std::nullopt.
std::optional<SegmentEdgeBlend> blend_between(int s, int a, int b, const Primitive& pa, const Primitive& pb,
                                              const SegmentContact& with_a, const SegmentContact& with_b,
                                              const FitSample& samples, double cap,
                                              const std::optional<PrimitiveType>& type, bool given = false)
{
  // Each border lies on its plane's kept half, beyond the edge as seen from the other border.
  const Eigen::Vector3d& ma = with_a.mean;
  const Eigen::Vector3d& mb = with_b.mean;
  const std::optional<EdgeSection> section = edge_section(pa, pb, 2 * ma - mb, 2 * mb - ma, 0.5 * (ma + mb));
  if (!section)
    return std::nullopt;
  const double ta = distance_along(*section, section->ray_a, with_a.mean);
  const double tb = distance_along(*section, section->ray_b, with_b.mean);
  const double setback = 0.5 * (ta + tb);
  if (!(ta > 0 && tb > 0) || !(given || std::abs(ta - tb) <= std::max(cap, kEdgeBlendBorderShare * setback)))
    return std::nullopt;
  std::optional<SegmentEdgeBlend> best;
  for (BlendForm form : {BlendForm::Fillet, BlendForm::Chamfer}) {
    if (type && *type != (form == BlendForm::Fillet ? PrimitiveType::Cylinder : PrimitiveType::Plane))
      continue;
    const double rms = capped_rms(samples, cap, [&](const Eigen::Vector3d& p) {
      return edge_blend_distance(*section, form, setback, p);
    });
    if (!best || rms < best->rms)
      best = SegmentEdgeBlend{s, a, b, *section, form, setback, rms, edge_blend_primitive(*section, form, setback)};
  }
  if (!best)
    return std::nullopt;
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
// its RMS. 0 when there is no such window.
double blend_gain(const SegmentEdgeBlend& blend, const SegmentSamples& own, const SegmentSamples& a,
                  const SegmentSamples& b, const Primitive& pa, const Primitive& pb, double tolerance)
{
  const EdgeSection& section = blend.section;
  EdgeBlendWindow window(section, tolerance);
  if (!(tolerance > 0) || !(blend.setback < window.max_setback()) || own.points.rows() == 0)
    return 0;
  const Eigen::VectorXd along_line = (own.points.rowwise() - section.origin.transpose()) * section.direction;
  const double lo = along_line.minCoeff(), hi = along_line.maxCoeff();
  for (Eigen::Index i = 0; i < own.points.rows(); ++i)
    window.add(own.points.row(i).transpose(), own.weights[i]);
  auto take_plane = [&](const SegmentSamples& s, const Eigen::Vector3d& ray, const Primitive& plane) {
    for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
      const Eigen::Vector3d p = s.points.row(i).transpose();
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

// The best-scoring blend of segment s between any two of the planes it touches, better than its own primitive.
// Failing that, the blend its samples and its planes' make likeliest against the sharp edge, by kMinBlendGain or
// more (blend_gain): the test the segmentation's carve made, for a segmentation that no longer has its records.
std::optional<SegmentEdgeBlend> best_blend_of(int s, const std::vector<std::optional<Primitive>>& primitives,
                                              const std::vector<SegmentSamples>& samples, const OwnFitScore& own,
                                              const std::vector<const SegmentContact*>& touching,
                                              const std::optional<PrimitiveType>& type)
{
  double best_score = own.score, best_gain = kMinBlendGain;
  std::optional<SegmentEdgeBlend> chosen, likeliest;
  for (std::size_t i = 0; i < touching.size(); ++i)
    for (std::size_t j = i + 1; j < touching.size(); ++j) {
      const int a = touching[i]->a == s ? touching[i]->b : touching[i]->a;
      const int b = touching[j]->a == s ? touching[j]->b : touching[j]->a;
      const std::optional<SegmentEdgeBlend> blend = blend_between(s, a, b, *primitives[std::size_t(a)],
                                                                  *primitives[std::size_t(b)], *touching[i],
                                                                  *touching[j], own.sample, own.cap, type);
      if (!blend)
        continue;
      const double score = type_score(blend->rms, 1, own.diagonal);
      if (blend->rms <= std::min(own.cap, kEdgeBlendRmsRatio * own.rms) && score < best_score) {
        best_score = score;
        chosen = blend;
      }
      if (chosen)
        continue;
      const double gain = blend_gain(*blend, samples[std::size_t(s)], samples[std::size_t(a)],
                                     samples[std::size_t(b)], *primitives[std::size_t(a)],
                                     *primitives[std::size_t(b)], own.cap);
      if (gain >= best_gain) {
        best_gain = gain;
        likeliest = blend;
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
    const int other = c->a == r.segment ? c->b : c->a;
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
                       *primitives[std::size_t(r.plane_b)], *with_a, *with_b, own->sample, own->cap, type, true);
}

} // namespace

std::vector<SegmentEdgeBlend> fit_edge_blends(const std::vector<std::optional<Primitive>>& primitives,
                                              const std::vector<SegmentSamples>& samples,
                                              const std::vector<SegmentContact>& contacts, double roughness,
                                              double tolerance, const std::vector<std::optional<PrimitiveType>>& types,
                                              const std::vector<SegmentBlendRecord>& given)
{
  const int count = int(std::min(primitives.size(), samples.size()));
  auto is_plane = [&](int k) {
    return k >= 0 && k < count && primitives[std::size_t(k)] &&
           primitives[std::size_t(k)]->type == PrimitiveType::Plane && primitive_is_valid(*primitives[std::size_t(k)]);
  };
  std::vector<std::vector<const SegmentContact*>> planes_of(std::size_t(std::max(count, 0)));
  for (const SegmentContact& c : contacts) {
    if (c.a < 0 || c.b < 0 || c.a >= count || c.b >= count || c.a == c.b || !c.mean.allFinite())
      continue;
    if (is_plane(c.b))
      planes_of[std::size_t(c.a)].push_back(&c);
    if (is_plane(c.a))
      planes_of[std::size_t(c.b)].push_back(&c);
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
    if (planes_of[std::size_t(s)].size() < 2 || role[std::size_t(s)] != kNone)
      continue;
    const std::optional<OwnFitScore> own =
        score_own_fit(samples[std::size_t(s)], primitives[std::size_t(s)], kEdgeBlendPoints, roughness, tolerance);
    if (!own)
      continue;
    if (std::optional<SegmentEdgeBlend> blend =
            best_blend_of(s, primitives, samples, *own, planes_of[std::size_t(s)], type_of(s)))
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
