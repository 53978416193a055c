// merge_regions.h: the second phase of segment_by_primitive_growing: adjacent grown regions that are one
// surface become one region.
//
// Input:  GrowingFaces, the FaceAdjacency, the GrowingRegions of grow_regions.h and its GrowingScale.
// Output: the regions merged in place: a merged region keeps the smaller id and the union's primitive, the
//         other keeps no faces; label follows. Returns the number of merges.
// Method: pairs of adjacent regions, longest shared border first, in rounds until nothing merges (after the
//         first round, only pairs with a region that merged in the round before). A pair merges when one
//         primitive agrees with each region over at least kMergeShare of its area (merged_primitive): the
//         share is measured per region, so that a small region of another surface is not outvoted, and
//         against the scan's own roughness: faces of one rough surface miss the tests here and there, those
//         of a surface meeting it at an edge almost all miss. Candidates are each region's primitive refined
//         on the union, so the types may differ (a piece of a wavy plane that growth fitted with a torus
//         joins the plane), except that a torus is tried only for two tori: it has the freedom to also fit a
//         fillet with the faces it joins. The candidate whose worse region agrees most wins.
// Cost:   O(E log E) for the borders; per round O(region adjacencies * (kFitSampleCount + kShareSampleCount)).
#ifndef PRIMITIVE_EDIT_MERGE_REGIONS_H
#define PRIMITIVE_EDIT_MERGE_REGIONS_H

#include "common/base/find_root.h"
#include "common/segment/fit_region_primitive.h"
#include "common/segment/grow_regions.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace primitive_edit {

constexpr double kMergeShare = 0.5; // share of each region that must agree with the union's primitive

inline std::optional<Primitive> merged_primitive(const GrowingFaces& g, const std::vector<int>& fa, const Primitive& pa,
                                                 const std::vector<int>& fb, const Primitive& pb,
                                                 const std::vector<int>& both, const GrowingScale& scale)
{
  const double tol = scale.tolerance, angle = scale.angle;
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
    if (!r.status.ok() || !primitive_is_valid(r.primitive) || curvature_radius(r.primitive) < scale.min_curvature_radius)
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

namespace merge_detail {

// (-shared edges, a, b) for every pair of adjacent regions a < b, longest border first.
inline std::vector<std::tuple<int, int, int>> region_borders(const FaceAdjacency& adj, const std::vector<int>& label)
{
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t f = 0; f < label.size(); ++f) {
    const int a = label[f];
    if (a < 0)
      continue;
    for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k) {
      const int b = label[std::size_t(adj.neighbour[std::size_t(k)])];
      if (b > a)
        pairs.emplace_back(a, b);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<std::tuple<int, int, int>> borders;
  for (std::size_t i = 0; i < pairs.size();) {
    std::size_t j = i;
    while (j < pairs.size() && pairs[j] == pairs[i])
      ++j;
    borders.emplace_back(-int(j - i), pairs[i].first, pairs[i].second);
    i = j;
  }
  std::sort(borders.begin(), borders.end());
  return borders;
}

} // namespace merge_detail

inline int merge_regions(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                         GrowingRegions& regions)
{
  using namespace merge_detail;
  const int count = int(regions.primitive.size());
  const std::vector<std::tuple<int, int, int>> borders = region_borders(adj, regions.label);
  std::vector<int> parent(static_cast<std::size_t>(count));
  for (int r = 0; r < count; ++r)
    parent[std::size_t(r)] = r;
  std::vector<int> merged_in(static_cast<std::size_t>(count), 0);
  std::vector<int> both;
  int total = 0;
  for (int round = 1, merges = 1; merges > 0; ++round) {
    merges = 0;
    for (const auto& border : borders) {
      const int a = find_root(parent, std::get<1>(border));
      const int b = find_root(parent, std::get<2>(border));
      if (a == b || (round > 1 && merged_in[std::size_t(a)] != round - 1 && merged_in[std::size_t(b)] != round - 1))
        continue;
      const std::vector<int>& fa = regions.faces[std::size_t(a)];
      const std::vector<int>& fb = regions.faces[std::size_t(b)];
      both = fa;
      both.insert(both.end(), fb.begin(), fb.end());
      const std::optional<Primitive> joint = merged_primitive(g, fa, regions.primitive[std::size_t(a)], fb,
                                                              regions.primitive[std::size_t(b)], both, scale);
      if (!joint)
        continue;
      const int keep = std::min(a, b), gone = std::max(a, b);
      parent[std::size_t(gone)] = keep;
      regions.primitive[std::size_t(keep)] = *joint;
      regions.faces[std::size_t(keep)].swap(both);
      std::vector<int>().swap(regions.faces[std::size_t(gone)]);
      merged_in[std::size_t(keep)] = round;
      ++merges;
    }
    total += merges;
  }
  for (int& l : regions.label)
    if (l >= 0)
      l = find_root(parent, l);
  return total;
}

} // namespace primitive_edit

#endif
