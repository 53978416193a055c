#include "common/segment/merge_regions.h"

#include "common/geometry/sagitta.h"

namespace primitive_edit {

std::optional<Primitive> merged_primitive(const GrowingFaces& g, const std::vector<int>& fa, const Primitive& pa,
                                          const std::vector<int>& fb, const Primitive& pb,
                                          const GrowingScale& scale)
{
  const double tol = scale.tolerance, angle = scale.angle;
  Eigen::MatrixX3d points, normals;
  Eigen::VectorXd weights;
  face_samples(g, fa, fb, kFitSampleCount, points, normals, weights);
  if (points.rows() < 3)
    return std::nullopt;
  std::optional<Primitive> best;
  double best_share = kMergeShare;
  const double diagonal = (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  FitOptions fast;
  fast.max_iterations = 10;
  auto consider = [&](FitResult r) {
    r = reduce_degenerate_cone(r, points, weights, tol, fast);
    // Refined on a wavy union, a sphere or cylinder may flatten out to a huge radius: within the tolerance
    // it is a plane, and is reported as one (as fit_primitive_auto would choose).
    const bool curved = r.primitive.type == PrimitiveType::Sphere || r.primitive.type == PrimitiveType::Cylinder;
    if (r.status.ok() && curved && sagitta(r.primitive.radius, diagonal) <= tol)
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
  if (pa.type != PrimitiveType::Torus || pb.type == PrimitiveType::Torus)
    consider(refine_primitive(pa, points, weights, fast));
  if (pb.type != pa.type && pb.type != PrimitiveType::Torus)
    consider(refine_primitive(pb, points, weights, fast));
  return best;
}

namespace merge_detail {

std::vector<std::tuple<int, int, int>> region_borders(const FaceAdjacency& adj, const std::vector<int>& label)
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

RegionPairs merge_regions(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                          GrowingRegions& regions, int threads)
{
  using namespace merge_detail;
  const int count = int(regions.primitive.size());
  const std::vector<std::tuple<int, int, int>> borders = region_borders(adj, regions.label);
  std::vector<int> parent(static_cast<std::size_t>(count));
  for (int r = 0; r < count; ++r)
    parent[std::size_t(r)] = r;
  auto roots = [&](std::size_t border) {
    return std::make_pair(find_root(parent, std::get<1>(borders[border])),
                          find_root(parent, std::get<2>(borders[border])));
  };
  std::vector<int> merged_in(static_cast<std::size_t>(count), 0);
  // After the first round only pairs with a region that merged in the round before are tested.
  auto tested = [&](std::pair<int, int> ab, int round) {
    return ab.first != ab.second && (round == 1 || merged_in[std::size_t(ab.first)] == round - 1 ||
                                     merged_in[std::size_t(ab.second)] == round - 1);
  };
  auto test = [&](std::pair<int, int> ab) {
    return merged_primitive(g, regions.faces[std::size_t(ab.first)], regions.primitive[std::size_t(ab.first)],
                            regions.faces[std::size_t(ab.second)], regions.primitive[std::size_t(ab.second)], scale);
  };
  // One thread tests one pair at a time; more take a window of pairs (see Method above).
  const std::size_t lanes = std::size_t(resolve_thread_count(threads));
  const std::size_t window_size = lanes > 1 ? kMergeWindowPerThread * lanes : 1;
  std::vector<std::size_t> window;
  std::vector<std::pair<int, int>> pair_of(window_size);
  std::vector<std::optional<Primitive>> joint(window_size);
  std::vector<int> changed_in_window(static_cast<std::size_t>(count), -1);
  int windows = 0;
  for (int round = 1, merges = 1; merges > 0; ++round) {
    merges = 0;
    for (std::size_t next = 0; next < borders.size();) {
      window.clear();
      for (; next < borders.size() && window.size() < window_size; ++next) {
        const std::pair<int, int> ab = roots(next);
        if (tested(ab, round)) {
          pair_of[window.size()] = ab;
          window.push_back(next);
        }
      }
      std::atomic<std::size_t> taken{0};
      // As many ranges as threads, one index each.
      parallel_for(std::min(lanes, window.size()), int(lanes), 1, [&](std::size_t, std::size_t) {
        for (std::size_t i; (i = taken++) < window.size();)
          joint[i] = test(pair_of[i]);
      });
      ++windows;
      for (std::size_t i = 0; i < window.size(); ++i) {
        const std::pair<int, int> ab = roots(window[i]);
        if (!tested(ab, round))
          continue;
        const auto [a, b] = ab;
        const bool fresh = ab == pair_of[i] && changed_in_window[std::size_t(a)] != windows &&
                           changed_in_window[std::size_t(b)] != windows;
        const std::optional<Primitive> merged = fresh ? joint[i] : test(ab);
        if (!merged)
          continue;
        const int keep = std::min(a, b), gone = std::max(a, b);
        parent[std::size_t(gone)] = keep;
        regions.primitive[std::size_t(keep)] = *merged;
        // The union's faces: a's, then b's (the order the test sampled, which later samples stride over too),
        // appended in place.
        std::vector<int>& fa = regions.faces[std::size_t(a)];
        std::vector<int>& fb = regions.faces[std::size_t(b)];
        fa.insert(fa.end(), fb.begin(), fb.end());
        std::vector<int>().swap(fb);
        if (keep != a)
          fa.swap(fb);
        merged_in[std::size_t(keep)] = round;
        changed_in_window[std::size_t(keep)] = windows;
        ++merges;
      }
    }
  }
  for (int& l : regions.label)
    if (l >= 0)
      l = find_root(parent, l);
  RegionPairs adjacent;
  for (std::size_t border = 0; border < borders.size(); ++border)
    if (const auto [a, b] = roots(border); a != b)
      adjacent.emplace_back(std::min(a, b), std::max(a, b));
  std::sort(adjacent.begin(), adjacent.end());
  adjacent.erase(std::unique(adjacent.begin(), adjacent.end()), adjacent.end());
  return adjacent;
}

} // namespace primitive_edit
