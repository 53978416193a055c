// segment_by_primitive_growing.h: automatic segmentation of a scan into primitive surfaces by
// fit-and-grow, for scans whose edges are blurred (CT) so that a normal-angle flood fill
// (segment_by_normal_angle.h) walks across them.
//
// Input:  a vcg triangle mesh, optionally its FaceAdjacency (built here otherwise), and parameters:
//         tolerance          a face joins a primitive when its centroid is within this distance of it
//                            (mesh units); <= 0: automatic, 3x the surface roughness, estimated as the
//                            median plane-fit RMS of small patches spread over the mesh (at least 1/20 of
//                            the mean edge length, so that exact data still gets a positive tolerance);
//         normal_angle_deg   ...and when its smoothed normal is within this angle of the primitive's normal
//                            there (either orientation: holes and bosses alike); the allowed angle grows
//                            linearly to twice this as the distance goes to 0 (see below);
//         seed_patch_faces   size of the patch a seed is fitted on;
//         min_region_faces   grown regions smaller than this are dissolved and their faces handed to the
//                            neighbours (<= 0: automatic, = seed_patch_faces);
//         smoothing_iterations passes of smooth_face_normals (noise in the normals and the seed order).
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
//            Then, smallest first, a region that agrees over half its area with a larger neighbour's
//            primitive at twice the tolerance (a crest or trough of the roughness, parallel to the
//            surface but beyond the tolerance) is dissolved.
//         4. the faces left over (blurred edges, fillets smaller than a patch, failed seeds, dissolved
//            regions) go, by a best-first flood (priority = distance to the region's primitive), to the
//            adjacent region whose primitive is nearest: a blurred edge between two planes is split at
//            their bisector. Then a few passes of boundary relaxation move each border face to the
//            neighbouring region whose primitive explains it best (growth within the tolerance lets a
//            plane take the tangent start of a fillet). Components with no region at all become one
//            segment each.
//         On a scan whose roughness is comparable to the size of its small features (fillets of radius
//         about the tolerance), those features go to the surfaces around them, split at the nearest one.
// Output: segment_of_face (indexed by vcg::tri::Index): dense ids 0..K-1, -1 for deleted faces. Returns K.
//         The optional report holds the tolerance used, the roughness estimate and each segment's
//         primitive (std::nullopt for a segment no primitive was grown for), in the form snap_segments.h
//         takes.
//         Faces without a defined normal (zero area, NaN/Inf coordinates) never seed or grow a region; the
//         final flood gives them the label of a neighbour.
// Complexity: O(F log F) time (seed sort and the final priority flood); growth visits each face O(1) times
//         per refit of its region, and refits happen at geometric size steps on subsamples of at most
//         kFitSampleCount faces, so fitting costs O(regions * log F * kFitSampleCount). Merging refits
//         each tested pair on kFitSampleCount faces and checks kShareSampleCount faces of each region, per
//         round: O(region adjacencies * rounds * (kFitSampleCount + kShareSampleCount)). O(F) memory.
#ifndef PRIMITIVE_EDIT_SEGMENT_BY_PRIMITIVE_GROWING_H
#define PRIMITIVE_EDIT_SEGMENT_BY_PRIMITIVE_GROWING_H

#include "common/base/constants.h"
#include "common/base/progress.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/mesh/compact_segment_ids.h"
#include "common/mesh/estimate_surface_roughness.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/face_centroids_and_areas.h"
#include "common/fit/fit_plane.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/base/primitive.h"
#include "common/fit/refine_primitive.h"
#include "common/mesh/smooth_face_normals.h"
#include "common/geometry/weighted_pca.h"

#include <Eigen/Core>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

namespace primitive_edit {

struct SegmentByPrimitiveGrowingParams
{
  double tolerance = 0;          // mesh units; <= 0: automatic from the roughness
  double normal_angle_deg = 30;  // face normal vs primitive normal
  int seed_patch_faces = 60;
  int min_region_faces = 0;      // <= 0: seed_patch_faces
  int smoothing_iterations = 10;
};

struct SegmentByPrimitiveGrowingReport
{
  double tolerance = 0;  // the distance tolerance used
  double roughness = 0;  // estimated RMS of the surface about local planes
  int grown_regions = 0; // regions grown before merging and dissolving
  std::vector<std::optional<Primitive>> primitive_of_segment;
};

namespace grow_detail {

constexpr int kFitSampleCount = 600; // faces a refit uses at most
constexpr int kBandRings = 3;        // rings around a stopped region that a type change must explain
constexpr int kRoughnessPatchDivisor = 200; // roughness patches hold 1/200 of the faces
constexpr int kRelaxPasses = 20;     // boundary relaxation passes at most
constexpr int kShareSampleCount = 2000; // faces an agreeing share is estimated on at most
constexpr double kMergeShare = 0.5;  // share of each region that must agree with the union's primitive

struct Geometry
{
  std::vector<Eigen::Vector3d> centroid, normal;
  std::vector<double> area;
  std::vector<char> valid; // finite centroid and defined normal
};

// Centroids, face areas and smoothed normals of all faces.
template <class MeshType>
Geometry face_geometry(const MeshType& m, const FaceAdjacency& adj, int smoothing_iterations)
{
  Geometry g;
  const std::size_t n = m.face.size();
  g.normal = smooth_face_normals(m, adj, std::max(0, smoothing_iterations));
  FaceCentroidsAndAreas faces = face_centroids_and_areas(m);
  g.centroid = std::move(faces.centroid);
  g.area = std::move(faces.area);
  g.valid.assign(n, 0);
  for (std::size_t f = 0; f < n; ++f) {
    if (g.normal[f].isZero(0.0)) {
      g.centroid[f].setZero();
      g.area[f] = 0.0;
    }
    g.valid[f] = g.area[f] > 0.0 ? 1 : 0;
  }
  return g;
}

// Fit samples (centroid, smoothed normal, area) of at most max_count faces, evenly strided over `faces`.
inline void face_samples(const Geometry& g, const std::vector<int>& faces, int max_count, Eigen::MatrixX3d& points,
                         Eigen::MatrixX3d& normals, Eigen::VectorXd& weights)
{
  const std::size_t n = faces.size();
  const std::size_t count = std::min(n, std::size_t(std::max(1, max_count)));
  points.resize(Eigen::Index(count), 3);
  normals.resize(Eigen::Index(count), 3);
  weights.resize(Eigen::Index(count));
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t f = std::size_t(faces[count == n ? i : (i * n) / count]);
    points.row(Eigen::Index(i)) = g.centroid[f].transpose();
    normals.row(Eigen::Index(i)) = g.normal[f].transpose();
    weights[Eigen::Index(i)] = g.area[f];
  }
}

// Does face f agree with the primitive: centroid within tol, normal within the angle (either side)? The
// allowed angle grows linearly to twice `angle` as the distance goes to 0: on a rough scan the surface's
// local slope is noise where the face lies on the primitive, while a face of another surface that meets it
// at an edge is near it only on a band narrower than tol.
inline bool agrees(const Geometry& g, const Primitive& prim, int f, double tol, double angle)
{
  const PrimitiveProjection pr = project_onto_primitive(prim, g.centroid[std::size_t(f)]);
  const double d = std::abs(pr.signed_distance);
  if (!(d <= tol))
    return false;
  const double c = std::min(1.0, std::abs(pr.normal.dot(g.normal[std::size_t(f)])));
  return std::acos(c) <= angle * (2.0 - d / tol);
}

// Share of `faces` (by area) that agree with the primitive.
inline double agreeing_share(const Geometry& g, const Primitive& prim, const std::vector<int>& faces, double tol,
                             double angle)
{
  double in = 0, all = 0;
  for (int f : faces) {
    all += g.area[std::size_t(f)];
    if (agrees(g, prim, f, tol, angle))
      in += g.area[std::size_t(f)];
  }
  return all > 0 ? in / all : 0.0;
}

// Breadth-first patch of at most max_faces faces from `start` over faces for which usable(f) holds.
template <class Usable>
void bfs_patch(const FaceAdjacency& adj, const std::vector<int>& starts, std::size_t max_faces, Usable usable,
               std::vector<int>& stamp, int mark, std::vector<int>& patch)
{
  patch.clear();
  for (int s : starts)
    if (stamp[std::size_t(s)] != mark && usable(s) && patch.size() < max_faces) {
      stamp[std::size_t(s)] = mark;
      patch.push_back(s);
    }
  for (std::size_t head = 0; head < patch.size() && patch.size() < max_faces; ++head) {
    const int f = patch[head];
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1] && patch.size() < max_faces; ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      if (stamp[std::size_t(h)] != mark && usable(h)) {
        stamp[std::size_t(h)] = mark;
        patch.push_back(h);
      }
    }
  }
}

// A primitive for the faces: refined from `start` when given, else fitted (plane first, then any type).
// Accepted when the faces agree with it over at least `share` of their area.
inline std::optional<Primitive> fit_faces(const Geometry& g, const std::vector<int>& faces, const Primitive* start,
                                          double tol, double angle, double share)
{
  Eigen::MatrixX3d points, normals;
  Eigen::VectorXd weights;
  face_samples(g, faces, kFitSampleCount, points, normals, weights);
  if (points.rows() < 3)
    return std::nullopt;
  auto accept = [&](const FitResult& r) {
    return r.status.ok() && primitive_is_valid(r.primitive) && agreeing_share(g, r.primitive, faces, tol, angle) >= share;
  };
  if (start) {
    FitOptions fast;
    fast.max_iterations = 10;
    const FitResult r = refine_primitive(*start, points, weights, fast);
    if (accept(r))
      return r.primitive;
    return std::nullopt;
  }
  const FitResult plane = fit_plane(points, normals, weights);
  if (accept(plane))
    return plane.primitive;
  AutoFitOptions options;
  options.tolerance = 0.5 * tol;
  const AutoFitResult best = fit_primitive_auto(points, normals, weights, options);
  if (best.status.ok() && accept(best.best))
    return best.best.primitive;
  return std::nullopt;
}

// A face's normal variation over its 1-ring: the seed order (flattest first).
inline std::vector<int> seed_order(const Geometry& g, const FaceAdjacency& adj)
{
  const std::size_t n = g.valid.size();
  std::vector<double> variation(n, std::numeric_limits<double>::infinity());
  std::vector<int> order;
  for (std::size_t f = 0; f < n; ++f) {
    if (!g.valid[f])
      continue;
    double v = 0;
    for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k) {
      const std::size_t h = std::size_t(adj.neighbour[std::size_t(k)]);
      v += 1.0 - (g.valid[h] ? g.normal[f].dot(g.normal[h]) : -1.0);
    }
    variation[f] = v / std::max(1, adj.offset[f + 1] - adj.offset[f]);
    order.push_back(int(f));
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return variation[std::size_t(a)] < variation[std::size_t(b)]; });
  return order;
}

// The smallest radius of curvature of a primitive (infinite for a plane; at the apex a cone has none).
inline double curvature_radius(const Primitive& p)
{
  switch (p.type) {
  case PrimitiveType::Sphere:
  case PrimitiveType::Cylinder: return p.radius;
  case PrimitiveType::Torus: return p.minor_radius;
  default: return std::numeric_limits<double>::infinity();
  }
}

// Share (by area) of `faces` that agree with the primitive, on at most kShareSampleCount evenly strided faces.
inline double sampled_share(const Geometry& g, const Primitive& prim, const std::vector<int>& faces, double tol,
                            double angle)
{
  const std::size_t n = faces.size();
  const std::size_t count = std::min<std::size_t>(n, kShareSampleCount);
  double in = 0, all = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const int f = faces[count == n ? i : (i * n) / count];
    all += g.area[std::size_t(f)];
    if (agrees(g, prim, f, tol, angle))
      in += g.area[std::size_t(f)];
  }
  return all > 0 ? in / all : 0.0;
}

// A primitive for the union of two adjacent regions that each of them agrees with over at least kMergeShare
// of its area, or nullopt. A region's agreeing share measures the union's fit against the scan's own
// roughness (faces of a rough surface miss the tolerance or the angle here and there, those of a
// surface meeting it at an edge almost all miss), and is not diluted when one region is much smaller.
// Tried: each region's primitive refined on the union, so the types may differ (a piece of a wavy plane
// that growth fitted with a torus joins the plane), except that a torus is only tried for two tori: it
// has the freedom to also fit a fillet with the faces it joins. The candidate whose worse region agrees
// most wins.
inline std::optional<Primitive> merged_primitive(const Geometry& g, const std::vector<int>& fa, const Primitive& pa,
                                                 const std::vector<int>& fb, const Primitive& pb,
                                                 const std::vector<int>& both, double tol, double angle,
                                                 double min_radius)
{
  Eigen::MatrixX3d points, normals;
  Eigen::VectorXd weights;
  face_samples(g, both, kFitSampleCount, points, normals, weights);
  if (points.rows() < 3)
    return std::nullopt;
  std::optional<Primitive> best;
  double best_share = kMergeShare;
  const double diagonal = (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  auto consider = [&](FitResult r) {
    // Refined on a wavy union, a sphere or cylinder may flatten out to a huge radius: within the tolerance
    // it is a plane, and is reported as one (as fit_primitive_auto would choose).
    const bool curved = r.primitive.type == PrimitiveType::Sphere || r.primitive.type == PrimitiveType::Cylinder;
    if (r.status.ok() && curved &&
        r.primitive.radius - std::sqrt(std::max(0.0, r.primitive.radius * r.primitive.radius - 0.25 * diagonal * diagonal)) <=
            tol)
      r = fit_plane(points, normals, weights);
    if (!r.status.ok() || !primitive_is_valid(r.primitive) || curvature_radius(r.primitive) < min_radius)
      return;
    const double share = std::min(sampled_share(g, r.primitive, fa, tol, angle),
                                  sampled_share(g, r.primitive, fb, tol, angle));
    if (share >= best_share) {
      best = r.primitive;
      best_share = share;
    }
  };
  FitOptions fast;
  fast.max_iterations = 10;
  if (pa.type != PrimitiveType::Torus || pb.type == PrimitiveType::Torus)
    consider(refine_primitive(pa, points, weights, fast));
  if (pb.type != pa.type && pb.type != PrimitiveType::Torus)
    consider(refine_primitive(pb, points, weights, fast));
  return best;
}

inline int find_root(std::vector<int>& parent, int s)
{
  while (parent[std::size_t(s)] != s) {
    parent[std::size_t(s)] = parent[std::size_t(parent[std::size_t(s)])];
    s = parent[std::size_t(s)];
  }
  return s;
}

} // namespace grow_detail

template <class MeshType>
int segment_by_primitive_growing(const MeshType& m, const FaceAdjacency& adj,
                                 const SegmentByPrimitiveGrowingParams& params, std::vector<int>& segment_of_face,
                                 SegmentByPrimitiveGrowingReport* report = nullptr, const Progress& progress = {})
{
  using namespace grow_detail;
  const int face_count = int(m.face.size());
  segment_of_face.assign(std::size_t(face_count), -1);
  if (report)
    *report = SegmentByPrimitiveGrowingReport();
  if (adj.face_count() != face_count || face_count == 0)
    return 0;

  report_progress(progress, 0, "Smoothing face normals");
  const Geometry g = face_geometry(m, adj, params.smoothing_iterations);
  const int patch_faces = std::max(8, params.seed_patch_faces);
  const int min_faces = params.min_region_faces > 0 ? params.min_region_faces : patch_faces;
  const double angle_deg = std::isfinite(params.normal_angle_deg)
                               ? std::min(std::max(params.normal_angle_deg, 1.0), 89.0)
                               : SegmentByPrimitiveGrowingParams().normal_angle_deg;
  const double angle = radians_from_degrees(angle_deg);

  std::vector<int> stamp(std::size_t(face_count), 0);
  int mark = 0;
  double edge_sum = 0;
  int edge_count = 0;
  for (int f = 0; f < face_count; ++f)
    if (g.valid[std::size_t(f)]) {
      // The mean edge of a triangle of area a is about sqrt(4a / sqrt(3)).
      edge_sum += std::sqrt(4.0 * g.area[std::size_t(f)] / std::sqrt(3.0));
      ++edge_count;
    }
  const double mean_edge = edge_count ? edge_sum / edge_count : 0.0;
  // A surface curved more tightly than a seed patch is wide is an edge rounded by the scanner (blur), not a
  // primitive: such regions are dissolved and their faces split between the neighbours.
  const double patch_radius = std::sqrt(double(patch_faces) * std::sqrt(3.0) / 4.0 * mean_edge * mean_edge / kPi);
  // Roughness is measured on patches of a fixed share of the surface, so that the estimate does not depend
  // on the resolution and sees noise that is correlated over more than a seed patch (CT scans).
  const double roughness =
      estimate_surface_roughness(g.centroid, g.area, adj, std::max(patch_faces, edge_count / kRoughnessPatchDivisor));
  double tol = params.tolerance > 0 ? params.tolerance : std::max(3.0 * roughness, 0.05 * mean_edge);
  if (!std::isfinite(tol) || !(tol > 0))
    tol = 0.0;

  // label: region id of a face, -1 unassigned. failed: faces no seed should be tried from.
  std::vector<int>& label = segment_of_face;
  std::vector<char> failed(std::size_t(face_count), 0);
  std::vector<Primitive> prim_of_region;
  std::vector<std::vector<int>> faces_of_region;
  report_progress(progress, 10, "Growing regions");
  const std::vector<int> order = tol > 0 ? seed_order(g, adj) : std::vector<int>();
  std::vector<int> patch, region, queue, band;
  auto unassigned = [&](int f) { return g.valid[std::size_t(f)] && label[std::size_t(f)] < 0; };
  std::size_t processed = 0;
  for (int seed : order) {
    ++processed;
    if ((processed & 0x3FFF) == 0)
      report_progress(progress, 10 + int(60.0 * double(processed) / double(order.size())), "Growing regions");
    if (!unassigned(seed) || failed[std::size_t(seed)])
      continue;
    bfs_patch(adj, {seed}, std::size_t(patch_faces), unassigned, stamp, ++mark, patch);
    std::optional<Primitive> prim;
    if (int(patch.size()) >= patch_faces / 2)
      prim = fit_faces(g, patch, nullptr, tol, angle, 0.9);
    if (!prim) {
      for (int f : patch)
        failed[std::size_t(f)] = 1;
      continue;
    }
    const int id = int(prim_of_region.size());
    region.assign(1, seed);
    label[std::size_t(seed)] = id;
    std::size_t fitted_size = patch.size();
    int type_changes = 0;
    for (;;) {
      // Grow from every face of the region: after a refit, faces rejected before may now agree.
      const int grow_mark = ++mark;
      queue = region;
      for (std::size_t head = 0; head < queue.size(); ++head) {
        const int f = queue[head];
        for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
          const int h = adj.neighbour[std::size_t(k)];
          if (stamp[std::size_t(h)] == grow_mark || !unassigned(h))
            continue;
          stamp[std::size_t(h)] = grow_mark;
          if (!agrees(g, *prim, h, tol, angle))
            continue;
          label[std::size_t(h)] = id;
          region.push_back(h);
          queue.push_back(h);
        }
        if (region.size() >= fitted_size + fitted_size / 2)
          break;
      }
      if (region.size() >= fitted_size + fitted_size / 2) {
        fitted_size = region.size();
        if (const std::optional<Primitive> refined = fit_faces(g, region, &*prim, tol, angle, 0.9))
          prim = refined;
        continue;
      }
      // Growth stopped: does a richer type explain the region and a band around it?
      if (type_changes >= 2 || int(region.size()) < min_faces)
        break;
      bfs_patch(adj, region, region.size() + region.size() / 2, [&](int f) { return label[std::size_t(f)] == id; },
                stamp, ++mark, band);
      const std::size_t inner = band.size();
      for (int ring = 0, begin = 0; ring < kBandRings; ++ring) {
        const int end = int(band.size());
        for (int i = begin; i < end; ++i) {
          const int f = band[std::size_t(i)];
          for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
            const int h = adj.neighbour[std::size_t(k)];
            if (stamp[std::size_t(h)] != mark && unassigned(h)) {
              stamp[std::size_t(h)] = mark;
              band.push_back(h);
            }
          }
        }
        begin = end;
      }
      if (band.size() == inner)
        break;
      std::optional<Primitive> wider = fit_faces(g, band, nullptr, tol, angle, 0.95);
      if (!wider || wider->type == prim->type)
        break;
      prim = wider;
      ++type_changes;
    }
    if (int(region.size()) < min_faces || curvature_radius(*prim) < patch_radius) {
      for (int f : region) {
        label[std::size_t(f)] = -1;
        failed[std::size_t(f)] = 1;
      }
      continue;
    }
    prim_of_region.push_back(*prim);
    faces_of_region.push_back(region);
  }
  const int grown = int(prim_of_region.size());

  // Merge adjacent regions whose union fits one primitive (merged_primitive), longest borders first.
  report_progress(progress, 70, "Merging regions");
  std::vector<std::tuple<int, int, int>> borders; // (-shared edges, a, b), a < b
  {
    std::vector<std::pair<int, int>> pairs;
    for (int f = 0; f < face_count; ++f) {
      const int a = label[std::size_t(f)];
      if (a < 0)
        continue;
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int b = label[std::size_t(adj.neighbour[std::size_t(k)])];
        if (b > a)
          pairs.emplace_back(a, b);
      }
    }
    std::sort(pairs.begin(), pairs.end());
    for (std::size_t i = 0; i < pairs.size();) {
      std::size_t j = i;
      while (j < pairs.size() && pairs[j] == pairs[i])
        ++j;
      borders.emplace_back(-int(j - i), pairs[i].first, pairs[i].second);
      i = j;
    }
    std::sort(borders.begin(), borders.end());
  }
  std::vector<int> parent(static_cast<std::size_t>(grown));
  for (int r = 0; r < grown; ++r)
    parent[std::size_t(r)] = r;
  // Rounds until nothing merges; after the first, only pairs with a region that merged in the round before.
  std::vector<int> merged_in(static_cast<std::size_t>(grown), 0);
  std::vector<int> both;
  for (int round = 1, merges = 1; merges > 0; ++round) {
    merges = 0;
    for (const auto& border : borders) {
      const int a = find_root(parent, std::get<1>(border));
      const int b = find_root(parent, std::get<2>(border));
      if (a == b || (round > 1 && merged_in[std::size_t(a)] != round - 1 && merged_in[std::size_t(b)] != round - 1))
        continue;
      const std::vector<int>& fa = faces_of_region[std::size_t(a)];
      const std::vector<int>& fb = faces_of_region[std::size_t(b)];
      both = fa;
      both.insert(both.end(), fb.begin(), fb.end());
      const std::optional<Primitive> joint = merged_primitive(
          g, fa, prim_of_region[std::size_t(a)], fb, prim_of_region[std::size_t(b)], both, tol, angle, patch_radius);
      if (!joint)
        continue;
      const int keep = std::min(a, b), gone = std::max(a, b);
      parent[std::size_t(gone)] = keep;
      prim_of_region[std::size_t(keep)] = *joint;
      faces_of_region[std::size_t(keep)].swap(both);
      std::vector<int>().swap(faces_of_region[std::size_t(gone)]);
      merged_in[std::size_t(keep)] = round;
      ++merges;
    }
  }
  for (int& l : label)
    if (l >= 0)
      l = find_root(parent, l);

  // A region that agrees with a larger neighbour's primitive at twice the tolerance over half its area is a
  // crest or trough of that surface's roughness: it is dissolved, and the flood below hands its faces to
  // the nearest primitives. Smallest first.
  std::vector<int> by_size;
  for (int r = 0; r < grown; ++r)
    if (!faces_of_region[std::size_t(r)].empty())
      by_size.push_back(r);
  std::stable_sort(by_size.begin(), by_size.end(), [&](int a, int b) {
    return faces_of_region[std::size_t(a)].size() < faces_of_region[std::size_t(b)].size();
  });
  std::vector<int> neighbours;
  for (int r : by_size) {
    const std::vector<int>& faces = faces_of_region[std::size_t(r)];
    neighbours.clear();
    for (int f : faces)
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int q = label[std::size_t(adj.neighbour[std::size_t(k)])];
        if (q >= 0 && q != r && faces_of_region[std::size_t(q)].size() > faces.size())
          neighbours.push_back(q);
      }
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    for (int q : neighbours)
      if (sampled_share(g, prim_of_region[std::size_t(q)], faces, 2.0 * tol, angle) >= kMergeShare) {
        for (int f : faces)
          label[std::size_t(f)] = -1;
        std::vector<int>().swap(faces_of_region[std::size_t(r)]);
        break;
      }
  }

  // Best-first flood of the leftover faces from the regions, nearest primitive first.
  report_progress(progress, 80, "Assigning the faces between regions");
  using Item = std::pair<double, std::pair<int, int>>; // (cost, (face, region))
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  auto cost = [&](int f, int r) {
    if (!g.valid[std::size_t(f)])
      return std::numeric_limits<double>::max();
    const PrimitiveProjection pr = project_onto_primitive(prim_of_region[std::size_t(r)], g.centroid[std::size_t(f)]);
    // A normal that disagrees counts like a distance of up to one tolerance.
    return std::abs(pr.signed_distance) + tol * (1.0 - std::abs(pr.normal.dot(g.normal[std::size_t(f)])));
  };
  auto push_neighbours = [&](int f, int r) {
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      if (label[std::size_t(h)] < 0 && !m.face[std::size_t(h)].IsD())
        heap.push({cost(h, r), {h, r}});
    }
  };
  for (int f = 0; f < face_count; ++f)
    if (label[std::size_t(f)] >= 0)
      push_neighbours(f, label[std::size_t(f)]);
  while (!heap.empty()) {
    const auto [f, r] = heap.top().second;
    heap.pop();
    if (label[std::size_t(f)] >= 0)
      continue;
    label[std::size_t(f)] = r;
    push_neighbours(f, r);
  }

  // Boundary relaxation: a face that a neighbouring region's primitive explains better moves there. Growth
  // within the tolerance lets the first region take the tangent start of the next surface (plane into
  // fillet); the scan's ground truth is the nearest surface.
  for (int pass = 0; pass < kRelaxPasses; ++pass) {
    int moved = 0;
    for (int f = 0; f < face_count; ++f) {
      const int own = label[std::size_t(f)];
      if (own < 0 || !g.valid[std::size_t(f)])
        continue;
      int best = own;
      double best_cost = -1;
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int r = label[std::size_t(adj.neighbour[std::size_t(k)])];
        if (r < 0 || r == best)
          continue;
        if (best_cost < 0)
          best_cost = cost(f, own);
        const double c = cost(f, r);
        if (c < best_cost) {
          best = r;
          best_cost = c;
        }
      }
      if (best != own) {
        label[std::size_t(f)] = best;
        ++moved;
      }
    }
    if (moved == 0)
      break;
  }

  // Whatever no region reached (no region in its component) becomes one segment per component.
  int next_id = grown;
  std::vector<char> primitive_region(std::size_t(grown), 1);
  for (int seed = 0; seed < face_count; ++seed) {
    if (label[std::size_t(seed)] >= 0 || m.face[std::size_t(seed)].IsD())
      continue;
    const int id = next_id++;
    label[std::size_t(seed)] = id;
    queue.assign(1, seed);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int h = adj.neighbour[std::size_t(k)];
        if (label[std::size_t(h)] < 0 && !m.face[std::size_t(h)].IsD()) {
          label[std::size_t(h)] = id;
          queue.push_back(h);
        }
      }
    }
  }

  // Compact ids in order of first appearance, keeping each one's primitive.
  std::vector<int> old_label(label);
  const int K = compact_segment_ids(label);
  if (report) {
    report->tolerance = tol;
    report->roughness = roughness;
    report->grown_regions = grown;
    report->primitive_of_segment.assign(std::size_t(K), std::nullopt);
    for (int f = 0; f < face_count; ++f) {
      const int old = old_label[std::size_t(f)];
      if (old >= 0 && old < grown)
        report->primitive_of_segment[std::size_t(label[std::size_t(f)])] = prim_of_region[std::size_t(old)];
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
  const FaceAdjacency adj = build_face_adjacency(m);
  return segment_by_primitive_growing(m, adj, params, segment_of_face, report, progress);
}

} // namespace primitive_edit

#endif
