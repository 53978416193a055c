// fit_all_segments.h: "Primitive: Fit All Segments": a primitive for every segment of a mesh and, if asked,
// every segment snapped onto its primitive. The filter, the benches and the fuzz target all run this.
//
// Input:  a vcg triangle mesh, its segment ids (index = vcg::tri::Index(m, face), -1 = none) and
//         FitAllSegmentsOptions: the RMS tolerance (0: automatic from the scan's roughness, see
//         fit_primitive_auto.h), optional types per segment (fitted as given instead of the automatic type),
//         whether to snap and how (SnapOptions), the threads (fit_segments.h), the scan's roughness if the caller
//         knows it, and a Progress.
// Output: FitAllSegmentsResult: per segment its FitResult (a failed status: free-form, and why), point count
//         and area (after the relations' refit, with its RMS and maximum residual there); the primitives (empty
//         where free-form); with relations on, the relations kept (a segment refitted about one of the part's
//         directions then is parallel to its plane, one refitted about a cylinder's axis has its coaxiality
//         instead, a fillet found between planes its tangencies), how many the check dropped, the segments
//         refitted about a direction, those refitted about a cylinder segment's axis and those given a fillet or
//         chamfer between two planes; the estimated roughness, counts per type, the fitted share of the area, the
//         SnapReport and the time of each stage. With snap, the mesh's vertices lie on the primitives, the primitives are
//         recorded on the mesh (segment_primitive_attribute.h) so that a later Snap Segment keeps sharp edges
//         against them, and normals and bounding box are updated.
//         A failed status, with the mesh untouched, when there are no segments, the tolerance is negative
//         or not finite, or relate_primitives refuses its input (bad relation options).
// Method: surface_roughness (options.roughness, or kept on the mesh by the segmentation, else estimated;
//         automatic tolerance or relations), gather_segment_samples, fit_segments and relate_primitives (both
//         on options.threads; segment_contacts for the tangencies), fit_profiles_about_directions,
//         fit_profiles_about_axes, fit_edge_blends
//         (with the same contacts, and the blends the segmentation kept on the mesh, segment_blends_attribute.h),
//         snap_segments (its fold repair on options.threads too).
// Cost:   O(F + V) for roughness and samples, the fits' cost divided by the threads, and snap_segments.
#ifndef PRIMITIVE_EDIT_FIT_ALL_SEGMENTS_H
#define PRIMITIVE_EDIT_FIT_ALL_SEGMENTS_H

#include "common/base/progress.h"
#include "common/base/status.h"
#include "common/mesh/count_segments.h"
#include "common/mesh/surface_roughness_attribute.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/mesh/segment_blends_attribute.h"
#include "common/mesh/segment_primitive_attribute.h"
#include "common/mesh/update_normals_and_bounds.h"
#include "common/mesh/segment_contacts.h"
#include "common/pipeline/fit_segments.h"
#include "common/relate/fit_edge_blends.h"
#include "common/relate/fit_profiles_about_axes.h"
#include "common/relate/fit_profiles_about_directions.h"
#include "common/relate/relate_primitives.h"
#include "common/snap/snap_segments.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

namespace primitive_edit {

struct FitAllSegmentsOptions
{
  double tolerance = 0;  // RMS limit of a fit; 0: automatic (3 x the scan's roughness, or 1% of the segment's size)
  std::vector<std::optional<PrimitiveType>> types;  // per segment, optional: fit this type (the benches' ceilings)
  FitOptions fit;
  bool relations = true;  // find parallel, perpendicular, coaxial... primitives and refit them together
  RelationOptions relation_options;
  bool snap = false;
  SnapOptions snap_options = fitted_snap_options();
  int threads = 0;  // <= 0: all hardware threads
  // The scan's roughness when the caller has measured it (the edit session, before its applies moved vertices
  // onto primitives); unset: kept on the mesh or estimated (surface_roughness_attribute.h).
  std::optional<double> roughness;
};

struct FitAllSegmentsResult
{
  Status status;
  std::vector<FitResult> fits;  // per segment
  std::vector<int> point_count;
  std::vector<double> area;
  SegmentPrimitives primitives;  // per segment; empty where free-form
  double roughness = 0;          // estimated when the tolerance is automatic, else 0
  int fitted = 0;
  int per_type[kPrimitiveTypeCount] = {0, 0, 0, 0, 0};
  double fitted_area = 0, total_area = 0;
  std::vector<Relation> relations;  // kept by the joint refit, in terms of segment ids; see Output
  int relations_dropped = 0;        // found, then dropped by the check after the refit
  double part_size = 0;             // the relations' length scale (RelatedPrimitives::length); 0 without them
  std::vector<SegmentProfile> profiles;   // segments given their profile about a cylinder segment's axis
  // Segments given their plane, cylinder, cone or torus about one of the part's directions (axis_segment: the plane
  // whose normal it follows).
  std::vector<SegmentProfile> profiles_about_directions;
  std::vector<SegmentEdgeBlend> blends;  // segments given a fillet or chamfer between two planes
  std::optional<SnapReport> snap;
  double fit_seconds = 0, relation_seconds = 0, snap_seconds = 0;  // roughness, samples and fits; relations; snapping

  int segment_count() const { return int(fits.size()); }
};

namespace fit_all_detail {

// Gives segment s the primitive p, its FitResult measured over the inliers of p's robust weights (as a fit reports
// it), and keeps the counts; false, with nothing changed, when p cannot be measured on the samples.
bool take_primitive(FitAllSegmentsResult& out, const std::vector<SegmentSamples>& samples, int s, const Primitive& p);

// The relations and the joint refit (relate_primitives), then the profiles about the part's directions
// (fit_profiles_about_directions, each replacing its segment's relations by its parallelism to the plane it
// follows), those about the cylinders' axes (fit_profiles_about_axes, by its coaxiality) and the fillets and
// chamfers between planes (fit_edge_blends; a fillet's relations are its tangencies, a chamfer has none). A failed
// status when relate_primitives refuses.
Status relate_and_blend(FitAllSegmentsResult& out, const std::vector<SegmentSamples>& samples,
                        const std::vector<SegmentContact>& contacts, const std::vector<SegmentBlendRecord>& given_blends,
                        const FitAllSegmentsOptions& options);

} // namespace fit_all_detail

template <class MeshType>
FitAllSegmentsResult fit_all_segments(MeshType& m, const std::vector<int>& segment_of_face,
                                      const FitAllSegmentsOptions& options, const Progress& progress = {})
{
  using Clock = std::chrono::steady_clock;
  FitAllSegmentsResult out;
  if (!std::isfinite(options.tolerance) || options.tolerance < 0) {
    out.status = Status::failure("the fit tolerance must be 0 (automatic) or positive");
    return out;
  }
  const int count = count_segments(segment_of_face);
  if (count == 0 || segment_of_face.size() != m.face.size()) {
    out.status = Status::failure("the mesh has no segments");
    return out;
  }

  auto t0 = Clock::now();
  AutoFitOptions fit_options;
  fit_options.tolerance = options.tolerance;
  fit_options.fit = options.fit;
  if (options.tolerance == 0 || options.relations)
    out.roughness = options.roughness ? *options.roughness : surface_roughness(m);
  if (options.tolerance == 0)
    fit_options.roughness = out.roughness;
  const std::vector<SegmentSamples> samples = gather_segment_samples(m, segment_of_face, count, options.threads);
  // The segmentation's blends join planes: their planes are fitted as planes, unless a type was asked.
  const std::vector<SegmentBlendRecord> given_blends = read_segment_blends(m, segment_of_face);
  std::vector<std::optional<PrimitiveType>> types = options.types;
  for (const SegmentBlendRecord& b : given_blends)
    for (int plane : {b.plane_a, b.plane_b})
      if (plane >= 0 && plane < count) {
        types.resize(std::max(types.size(), std::size_t(count)));
        if (!types[std::size_t(plane)])
          types[std::size_t(plane)] = PrimitiveType::Plane;
      }
  out.fits = fit_segments(samples, types, fit_options, options.threads,
                          progress_range(progress, 0, options.snap ? 80 : 100));
  out.primitives.resize(size_t(count));
  for (int s = 0; s < count; ++s) {
    const SegmentSamples& seg = samples[size_t(s)];
    out.point_count.push_back(int(seg.points.rows()));
    out.area.push_back(seg.area);
    out.total_area += seg.area;
    const FitResult& fit = out.fits[size_t(s)];
    if (fit.status.ok()) {
      out.primitives[size_t(s)] = fit.primitive;
      ++out.per_type[int(fit.primitive.type)];
      ++out.fitted;
      out.fitted_area += seg.area;
    }
  }
  out.fit_seconds = std::chrono::duration<double>(Clock::now() - t0).count();

  if (options.relations && out.fitted >= 2) {
    t0 = Clock::now();
    report_progress(progress, options.snap ? 80 : 95, "Relating primitives");
    const Status related =
        fit_all_detail::relate_and_blend(out, samples, segment_contacts(m, segment_of_face), given_blends, options);
    if (!related) {
      out.status = related;
      return out;
    }
    out.relation_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  if (!options.snap)
    return out;

  report_progress(progress, 85, "Snapping segments");
  t0 = Clock::now();
  SnapOptions snap_options = options.snap_options;
  snap_options.threads = options.threads;
  out.snap = snap_segments(m, segment_of_face, out.primitives, snap_options);
  write_segment_primitives(m, out.primitives);
  update_normals_and_bounds(m);
  out.snap_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return out;
}

} // namespace primitive_edit

#endif
