// segment_by_primitive_growing.h: automatic segmentation of a scan into primitive surfaces by
// fit-and-grow, for scans whose edges are blurred (CT) so that a normal-angle flood fill
// (segment_by_normal_angle.h) walks across them.
//
// Input:  a vcg triangle mesh, optionally its FaceAdjacency (built here otherwise), and parameters:
//         tolerance          a face joins a primitive when its centroid is within this distance of it
//                            (mesh units); <= 0: automatic, 3x the surface roughness
//                            (estimate_surface_roughness.h, on patches of 1/200 of the faces; at least 1/20
//                            of the mean edge length, so that exact data still gets a positive tolerance);
//         normal_angle_deg   ...and when its smoothed normal is within this angle of the primitive's normal
//                            there (either orientation: holes and bosses alike); the allowed angle grows
//                            linearly to twice this as the distance goes to 0 (see below);
//         seed_patch_faces   size of the patch a seed is fitted on;
//         min_region_faces   grown regions smaller than this are dissolved and their faces handed to the
//                            neighbours (<= 0: automatic, = seed_patch_faces);
//         smoothing_iterations passes of smooth_face_normals (noise in the normals and the seed order);
//         roughness          the scan's roughness when a filter before measured it (surface_roughness_attribute.h);
//                            <= 0: estimated here.
// Method: 1. smoothed face normals; seeds ordered by flatness (the normal's variation over the 1-ring).
//         2. from the flattest unassigned seed: a patch of seed_patch_faces faces (BFS), fitted by a plane,
//            else by fit_primitive_auto; a patch that fits nothing marks all its faces as failed seeds.
//            The region grows by BFS over unassigned faces that agree with the primitive (distance, and
//            normal with the angle widened near the primitive: on a rough scan, e.g. CT with a smooth
//            random displacement, the local slope of a face that lies on the surface is noise, while a
//            face of another surface meeting it at an edge is near it only within a band narrower than
//            the tolerance); the primitive is refined on a subsample (refine_primitive) each time the
//            region has grown by half; when growth stops, fit_primitive_auto on the region plus a band of
//            a few rings around it may change the type (a plane patch that is part of a large cylinder)
//            and growth resumes.
//         3. grown regions smaller than min_region_faces, or curved more tightly than a seed patch is wide
//            (an edge rounded by the scanner's blur, not a CAD surface), are dissolved.
//            Adjacent regions are merged, longest borders first and in rounds until nothing merges, when
//            one primitive of any type (each region's primitive refined on the union; a torus only for two
//            tori, as a torus also fits a fillet with the faces it joins) agrees with each region over at
//            least half of its area. The share is measured per region, so that a small region of another
//            surface is not outvoted, and against the scan's own roughness: faces of one rough surface
//            miss the tests here and there, those of a surface meeting it at an edge almost all miss.
//            Then, smallest first, a region whose faces agree over half its area with its larger
//            neighbours' primitives at twice the tolerance, face by face any of them (a crest or trough of
//            the roughness, parallel to a surface but beyond the tolerance; a strip of a blurred edge that
//            the two surfaces beside it explain), is dissolved.
//         4. the faces left over (blurred edges, fillets smaller than a patch, failed seeds, dissolved
//            regions) go, by a best-first flood (priority = distance to the region's primitive), to the
//            adjacent region whose primitive is nearest: a blurred edge between two planes is split at
//            their bisector. Then a few passes of boundary relaxation move each border face to the
//            neighbouring region whose primitive explains it best (growth within the tolerance lets a
//            plane take the tangent start of a fillet). Components with no region at all become one
//            segment each.
//         5. on a scan whose roughness is comparable to the size of its small features, a fillet or chamfer
//            that stands off its sharp edge by less than the tolerance went to the two planes it joins, split
//            at their bisector: each pair of adjacent plane regions is tested for one by the likelihood of its
//            faces under the scan's own scatter (carve_edge_blends.h), and a blend found becomes a segment of
//            its own. The report lists them; the filter keeps them on the mesh for Fit All
//            (segment_blends_attribute.h), which makes them the blends of their planes. Off with
//            params.carve_blends = false (long waves of the roughness can read as a blend: its Limits).
// Phases: growing_faces.h (normals, the face tests), grow_regions.h (step 2), merge_regions.h and
//         dissolve_rough_regions.h (step 3), assign_leftover_faces.h and relax_region_borders.h (step 4),
//         carve_edge_blends.h (step 5); each is timed in the report.
// Output: segment_of_face (indexed by vcg::tri::Index): dense ids 0..K-1, -1 for deleted faces. Returns K.
//         The optional report holds the tolerance used, the roughness, each segment's primitive
//         (std::nullopt for a segment no primitive was grown for, in the form snap_segments.h takes), the
//         segments carved as blends with their two planes, and each phase's wall-clock time.
//         Faces without a defined normal (zero area, NaN/Inf coordinates) never seed or grow a region; the
//         final flood gives them the label of a neighbour.
// Complexity: O(F log F) time (the final priority flood; the seed order is sorted bucket by bucket); growth
//         visits each face O(1) times per refit of its region, and refits happen at geometric size steps on
//         subsamples of at most kFitSampleCount faces, so fitting costs O(regions * log F * kFitSampleCount).
//         Merging refits each tested pair on kFitSampleCount faces and checks kShareSampleCount faces of each
//         region, per round: O(region adjacencies * rounds * (kFitSampleCount + kShareSampleCount)). The blends:
//         O(faces near the planes' shared borders + plane pairs * kBlendPoints * setbacks tried). O(F) memory.
#ifndef PRIMITIVE_EDIT_SEGMENT_BY_PRIMITIVE_GROWING_H
#define PRIMITIVE_EDIT_SEGMENT_BY_PRIMITIVE_GROWING_H

#include "common/base/constants.h"
#include "common/base/huge_page_vector.h"
#include "common/base/known_scale.h"
#include "common/base/primitive.h"
#include "common/base/progress.h"
#include "common/base/status.h"
#include "common/mesh/compact_segment_ids.h"
#include "common/mesh/estimate_surface_roughness.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/segment_blends_attribute.h"
#include "common/segment/assign_leftover_faces.h"
#include "common/segment/carve_edge_blends.h"
#include "common/segment/dissolve_rough_regions.h"
#include "common/segment/grow_regions.h"
#include "common/segment/growing_faces.h"
#include "common/segment/merge_regions.h"
#include "common/segment/relax_region_borders.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace primitive_edit {

struct SegmentByPrimitiveGrowingParams
{
  double tolerance = 0;          // mesh units; <= 0: automatic from the roughness
  double normal_angle_deg = 30;  // face normal vs primitive normal
  int seed_patch_faces = 60;
  int min_region_faces = 0;      // <= 0: seed_patch_faces
  int smoothing_iterations = 10;
  bool carve_blends = true;      // step 5: fillets and chamfers hidden in their planes become segments
  double roughness = 0;          // the scan's roughness when already known (surface_roughness_attribute.h);
                                 // <= 0 or not finite: estimated
  int threads = 0;               // for the face tables, the seed order, the roughness and the merge tests (<= 0:
                                 // all); the result does not depend on it
};

// The ranges a user's parameters must lie in; the segmentation itself keeps within them whatever it is given
// (for the fuzz target), so adapters check first and refuse, rather than have a number silently changed.
constexpr double kMinGrowingNormalAngleDeg = 1.0, kMaxGrowingNormalAngleDeg = 89.0;
constexpr int kMinSeedPatchFaces = 8;
constexpr int kMaxSmoothingIterations = 1000;

// Refuses parameters out of range, naming them as the filter's dialog does.
Status check_primitive_growing_params(const SegmentByPrimitiveGrowingParams& params);

// Wall-clock seconds one phase took (for benches: bench/bench_segment_parts.cpp).
struct SegmentPhaseTime
{
  const char* phase;
  double seconds;
};

struct SegmentByPrimitiveGrowingReport
{
  double tolerance = 0;  // the distance tolerance used
  double roughness = 0;  // estimated RMS of the surface about local planes
  int grown_regions = 0; // regions grown before merging and dissolving
  std::vector<std::optional<Primitive>> primitive_of_segment;
  std::vector<SegmentBlendRecord> blends;  // segments carved as the fillet or chamfer of two plane segments
  std::vector<SegmentPhaseTime> phase_times;
};

namespace grow_detail {

// The mean edge length: a triangle of area a has a mean edge of about sqrt(4a / sqrt(3)).
double mean_edge_length(const GrowingFaces& g);

// Records the seconds since the last call under `phase`.
class PhaseClock
{
public:
  explicit PhaseClock(std::vector<SegmentPhaseTime>* out) : out_(out) {}
  void lap(const char* phase)
  {
    const auto now = std::chrono::steady_clock::now();
    if (out_)
      out_->push_back({phase, std::chrono::duration<double>(now - last_).count()});
    last_ = now;
  }

private:
  std::vector<SegmentPhaseTime>* out_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

} // namespace grow_detail

template <class MeshType>
int segment_by_primitive_growing(const MeshType& m, const FaceAdjacency& adj,
                                 const SegmentByPrimitiveGrowingParams& params, std::vector<int>& segment_of_face,
                                 SegmentByPrimitiveGrowingReport* report = nullptr, const Progress& progress = {})
{
  using namespace grow_detail;
  const int face_count = int(m.face.size());
  assign_on_huge_pages(segment_of_face, std::size_t(face_count), -1);
  if (report)
    *report = SegmentByPrimitiveGrowingReport();
  if (adj.face_count() != face_count || face_count == 0)
    return 0;
  PhaseClock clock(report ? &report->phase_times : nullptr);

  report_progress(progress, 0, "Smoothing face normals");
  const GrowingFaces g = growing_faces(m, adj, params.smoothing_iterations, params.threads);
  clock.lap("normals");

  GrowingScale scale;
  scale.seed_patch_faces = std::max(kMinSeedPatchFaces, params.seed_patch_faces);
  scale.min_region_faces = params.min_region_faces > 0 ? params.min_region_faces : scale.seed_patch_faces;
  scale.angle = radians_from_degrees(std::isfinite(params.normal_angle_deg)
                                         ? std::min(std::max(params.normal_angle_deg, kMinGrowingNormalAngleDeg),
                                                    kMaxGrowingNormalAngleDeg)
                                         : SegmentByPrimitiveGrowingParams().normal_angle_deg);
  const double mean_edge = mean_edge_length(g);
  // A surface curved more tightly than a seed patch is wide is an edge rounded by the scanner (blur), not a
  // primitive: such regions are dissolved and their faces split between the neighbours.
  scale.min_curvature_radius =
      std::sqrt(double(scale.seed_patch_faces) * std::sqrt(3.0) / 4.0 * mean_edge * mean_edge / kPi);
  // The scan's roughness is the mesh's, not this segmentation's: the same estimate (patches of a fixed share
  // of the surface) that the attribute keeps and the fit filters measure, whatever the seed patch size.
  const double roughness = is_known_scale(params.roughness)
                               ? params.roughness
                               : estimate_surface_roughness(g.centroid, g.area, adj, 0, params.threads);
  double tol = params.tolerance > 0 ? params.tolerance : std::max(3.0 * roughness, 0.05 * mean_edge);
  scale.tolerance = std::isfinite(tol) && tol > 0 ? tol : 0.0;
  clock.lap("roughness");

  report_progress(progress, 10, "Growing regions");
  GrowingRegions regions = grow_regions(g, adj, scale, progress_range(progress, 10, 70), params.threads);
  const int grown = int(regions.primitive.size());
  clock.lap("grow");

  report_progress(progress, 70, "Merging regions");
  const RegionPairs adjacent = merge_regions(g, adj, scale, regions, params.threads);
  clock.lap("merge");
  dissolve_rough_regions(g, adjacent, scale, regions);
  clock.lap("dissolve");

  report_progress(progress, 80, "Assigning the faces between regions");
  std::vector<int>& label = regions.label;
  assign_leftover_faces(g, adj, regions.primitive, scale.tolerance, label);
  clock.lap("assign");
  relax_region_borders(g, adj, regions.primitive, scale.tolerance, label, params.threads);
  clock.lap("relax");
  std::vector<CarvedBlend> blends;
  if (params.carve_blends) {
    report_progress(progress, 90, "Finding fillets and chamfers between planes");
    blends = carve_edge_blends(g, adj, regions.primitive, scale, label, params.threads);
  }
  clock.lap("blends");

  // Compact ids in order of first appearance, keeping each one's primitive.
  segment_of_face = label;
  const int K = compact_segment_ids(segment_of_face);
  if (report) {
    report->tolerance = scale.tolerance;
    report->roughness = roughness;
    report->grown_regions = grown;
    report->primitive_of_segment.assign(std::size_t(K), std::nullopt);
    std::vector<int> segment_of_label(std::size_t(*std::max_element(label.begin(), label.end()) + 1), -1);
    for (int f = 0; f < face_count; ++f) {
      const int old = label[std::size_t(f)];
      if (old < 0)
        continue;
      segment_of_label[std::size_t(old)] = segment_of_face[std::size_t(f)];
      if (old < grown)
        report->primitive_of_segment[std::size_t(segment_of_face[std::size_t(f)])] =
            regions.primitive[std::size_t(old)];
    }
    for (const CarvedBlend& b : blends) {
      const SegmentBlendRecord r{segment_of_label[std::size_t(b.label)], segment_of_label[std::size_t(b.plane_a)],
                                 segment_of_label[std::size_t(b.plane_b)]};
      report->primitive_of_segment[std::size_t(r.segment)] = b.primitive;
      report->blends.push_back(r);
    }
  }
  report_progress(progress, 100, "Segmentation done");
  return K;
}

template <class MeshType>
int segment_by_primitive_growing(const MeshType& m, const SegmentByPrimitiveGrowingParams& params,
                                 std::vector<int>& segment_of_face, SegmentByPrimitiveGrowingReport* report = nullptr,
                                 const Progress& progress = {})
{
  report_progress(progress, 0, "Building face adjacency");
  const FaceAdjacency adj = build_face_adjacency(m, params.threads);
  return segment_by_primitive_growing(m, adj, params, segment_of_face, report, progress);
}

} // namespace primitive_edit

#endif
