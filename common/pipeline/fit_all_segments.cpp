#include "common/pipeline/fit_all_segments.h"

#include <algorithm>

namespace primitive_edit {
namespace fit_all_detail {

bool take_primitive(FitAllSegmentsResult& out, const std::vector<SegmentSamples>& samples, int s, const Primitive& p)
{
  const SegmentSamples& seg = samples[std::size_t(s)];
  const double extent =
      seg.points.rows() ? (seg.points.colwise().maxCoeff() - seg.points.colwise().minCoeff()).norm() : 0.0;
  const double floor = 1e-9 * std::max(extent, 1e-300);
  Eigen::VectorXd used = refine_detail::tukey_weights(p, seg.points, seg.weights, 1.0, floor);
  for (Eigen::Index i = 0; i < used.size(); ++i)
    used[i] = used[i] > 0 ? seg.weights[i] : 0.0;
  const FitResult refit = fit_residuals(p, seg.points, used);
  if (!refit.status.ok())
    return false;
  FitResult& fit = out.fits[std::size_t(s)];
  if (fit.status.ok()) {
    --out.per_type[int(fit.primitive.type)];
  } else {
    ++out.fitted;
    out.fitted_area += seg.area;
  }
  ++out.per_type[int(p.type)];
  fit = refit;
  out.primitives[std::size_t(s)] = p;
  return true;
}

namespace {

// Forgets segment s's relations when, after the joint refit, it is given a primitive they were not found for.
void drop_relations_of(FitAllSegmentsResult& out, int s)
{
  out.relations.erase(std::remove_if(out.relations.begin(), out.relations.end(),
                                     [s](const Relation& r) { return r.a == s || r.b == s; }),
                      out.relations.end());
}

// A segment given a new primitive by a later step is no longer one of an earlier step's profiles.
void forget_profile(FitAllSegmentsResult& out, int s)
{
  for (std::vector<SegmentProfile>* list : {&out.profiles, &out.profiles_about_directions})
    list->erase(std::remove_if(list->begin(), list->end(), [s](const SegmentProfile& q) { return q.segment == s; }),
                list->end());
}

// Gives each profile's segment its primitive; its relations become the one that holds it to the segment it turns
// about (`kind_of` the profile).
template <class RelationKindOf>
void take_profiles(FitAllSegmentsResult& out, const std::vector<SegmentSamples>& samples,
                   const std::vector<SegmentProfile>& found, std::vector<SegmentProfile>& list, RelationKindOf kind_of)
{
  for (const SegmentProfile& q : found) {
    if (!take_primitive(out, samples, q.segment, q.primitive))
      continue;
    forget_profile(out, q.segment);
    list.push_back(q);
    drop_relations_of(out, q.segment);
    Relation r;
    r.kind = kind_of(q.primitive);
    r.a = q.axis_segment;
    r.b = q.segment;
    r.sign = q.primitive.type != PrimitiveType::Sphere &&
                     out.primitives[std::size_t(q.axis_segment)]->axis.dot(q.primitive.axis) < 0
                 ? -1.0
                 : 1.0;
    out.relations.push_back(r);
  }
}

// Fillets and chamfers, given the planes, cylinders and cones they join as the relations hold them; a fillet's
// relations are its tangencies.
void take_edge_blends(FitAllSegmentsResult& out, const std::vector<SegmentSamples>& samples,
                      const std::vector<SegmentEdgeBlend>& found)
{
  for (const SegmentEdgeBlend& b : found) {
    if (!take_primitive(out, samples, b.segment, b.primitive))
      continue;
    out.blends.push_back(b);
    drop_relations_of(out, b.segment);
    forget_profile(out, b.segment);
    if (b.form != BlendForm::Fillet)
      continue;
    for (int joined : {b.plane_a, b.plane_b}) {
      const Primitive& q = *out.primitives[std::size_t(joined)];
      Relation r;
      r.kind = RelationKind::Tangent;
      r.a = b.segment;
      r.b = joined;
      r.contact = joined == b.plane_a ? b.contact_a : b.contact_b;
      r.sign = project_onto_primitive(q, fillet_spine_point(b.primitive, r.contact)).signed_distance < 0 ? -1.0 : 1.0;
      out.relations.push_back(r);
    }
  }
}

} // namespace

Status relate_and_blend(FitAllSegmentsResult& out, const std::vector<SegmentSamples>& samples,
                        const std::vector<SegmentContact>& contacts, const std::vector<SegmentBlendRecord>& given_blends,
                        const FitAllSegmentsOptions& options)
{
  const RelatedPrimitives related = relate_primitives(out.primitives, samples, contacts, out.roughness,
                                                      options.relation_options, {}, options.threads);
  if (!related.status)
    return Status::failure("relations: " + related.status.error);
  out.relations = related.relations;
  out.relations_dropped = related.dropped;
  out.part_size = related.length;
  for (int s = 0; s < out.segment_count(); ++s) {
    const std::optional<Primitive>& p = related.primitives[std::size_t(s)];
    if (p && out.fits[std::size_t(s)].status.ok())
      take_primitive(out, samples, s, *p);
  }
  const double angle = options.relation_options.angle_deg;
  // Curved segments whose axis follows none of the part's directions, refitted about them: held parallel to the
  // plane whose normal they turn about. Before the profiles about axes: a hole found here is an axis there.
  take_profiles(out, samples,
                fit_profiles_about_directions(out.primitives, samples, out.roughness, options.tolerance,
                                              part_directions(out.primitives, out.area, angle), angle, options.types,
                                              options.threads),
                out.profiles_about_directions, [](const Primitive&) { return RelationKind::Parallel; });
  // Spheres, cones and tori turning about a hole's or boss's axis, as the relations hold it: their profile about
  // it. Their relations were those of their former type; now they share that axis.
  take_profiles(out, samples,
                fit_profiles_about_axes(out.primitives, samples, out.roughness, options.tolerance, angle,
                                        related.distance, options.types),
                out.profiles, [](const Primitive& p) {
                  return p.type == PrimitiveType::Sphere ? RelationKind::Concentric : RelationKind::Coaxial;
                });
  take_edge_blends(out, samples,
                   fit_edge_blends(out.primitives, samples, contacts, out.roughness, options.tolerance, options.types,
                                   given_blends, angle));
  return Status::success();
}

} // namespace fit_all_detail
} // namespace primitive_edit
