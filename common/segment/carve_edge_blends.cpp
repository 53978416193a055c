#include "common/segment/carve_edge_blends.h"

#include "common/base/parallel_for.h"
#include "common/geometry/edge_blend.h"
#include "common/geometry/edge_blend_likelihood.h"
#include "common/geometry/edge_blend_window.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace primitive_edit {

namespace {

// Two plane regions that share a border: the faces on either side of it and the number of shared edges.
struct PlanePair
{
  int a = -1, b = -1;
  std::vector<int> border;
  int edges = 0;
};

std::vector<PlanePair> adjacent_plane_pairs(const GrowingFaces& g, const FaceAdjacency& adj,
                                            const std::vector<Primitive>& primitive_of_region,
                                            const std::vector<int>& label)
{
  const int regions = int(primitive_of_region.size());
  auto is_plane = [&](int r) {
    return r >= 0 && r < regions && primitive_of_region[std::size_t(r)].type == PrimitiveType::Plane;
  };
  std::map<std::pair<int, int>, PlanePair> pairs;
  for (int f = 0; f < int(label.size()); ++f) {
    const int a = label[std::size_t(f)];
    if (!is_plane(a) || !g.valid[std::size_t(f)])
      continue;
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      const int b = label[std::size_t(h)];
      if (b <= a || !is_plane(b) || !g.valid[std::size_t(h)])
        continue;
      PlanePair& p = pairs[{a, b}];
      p.a = a, p.b = b;
      p.border.push_back(f);
      p.border.push_back(h);
      ++p.edges;
    }
  }
  std::vector<PlanePair> out;
  for (auto& [key, p] : pairs) {
    std::sort(p.border.begin(), p.border.end());
    p.border.erase(std::unique(p.border.begin(), p.border.end()), p.border.end());
    out.push_back(std::move(p));
  }
  return out;
}

// The faces of the pair's two regions about their common line: walked from the border, within the window's reach
// of the line and within the border's extent along it.
std::vector<int> edge_band(const GrowingFaces& g, const FaceAdjacency& adj, const std::vector<int>& label,
                           const PlanePair& pair, const PlanesLine& line, double reach, FaceStamps& stamps)
{
  double lo = 0, hi = 0;
  for (std::size_t i = 0; i < pair.border.size(); ++i) {
    const double t = (g.centroid[std::size_t(pair.border[i])] - line.origin).dot(line.direction);
    lo = i == 0 ? t : std::min(lo, t);
    hi = i == 0 ? t : std::max(hi, t);
  }
  auto usable = [&](int f) {
    const int l = label[std::size_t(f)];
    if (!g.valid[std::size_t(f)] || (l != pair.a && l != pair.b))
      return false;
    const Eigen::Vector3d q = g.centroid[std::size_t(f)] - line.origin;
    const double t = q.dot(line.direction);
    return t >= lo && t <= hi && (q - t * line.direction).norm() <= std::sqrt(2.0) * reach;
  };
  std::vector<int> band;
  bfs_patch(adj, pair.border, label.size(), usable, stamps, band);
  return band;
}

struct BlendCandidate
{
  CarvedBlend blend;
  double gain = 0;
  std::vector<int> faces; // of the band, between the tangent lines
};

std::optional<BlendCandidate> blend_of_pair(const GrowingFaces& g, const FaceAdjacency& adj,
                                            const std::vector<Primitive>& primitive_of_region,
                                            const GrowingScale& scale, const std::vector<int>& label,
                                            const PlanePair& pair, FaceStamps& stamps)
{
  const Primitive& pa = primitive_of_region[std::size_t(pair.a)];
  const Primitive& pb = primitive_of_region[std::size_t(pair.b)];
  Eigen::Vector3d near = Eigen::Vector3d::Zero();
  for (int f : pair.border)
    near += g.centroid[std::size_t(f)];
  near /= double(pair.border.size());
  const std::optional<PlanesLine> line = planes_line(pa, pb, near);
  if (!line)
    return std::nullopt;
  const double reach = kBlendReachTolerances * scale.tolerance;
  const double max_setback = kBlendSetbackTolerances * scale.tolerance;
  const std::vector<int> band = edge_band(g, adj, label, pair, *line, reach, stamps);
  // The half of each plane the part keeps is where that region's faces of the band lie.
  Eigen::Vector3d kept_a = Eigen::Vector3d::Zero(), kept_b = Eigen::Vector3d::Zero();
  double wa = 0, wb = 0;
  for (int f : band) {
    const bool in_a = label[std::size_t(f)] == pair.a;
    (in_a ? kept_a : kept_b) += g.area[std::size_t(f)] * g.centroid[std::size_t(f)];
    (in_a ? wa : wb) += g.area[std::size_t(f)];
  }
  if (!(wa > 0 && wb > 0))
    return std::nullopt;
  const std::optional<EdgeSection> section = edge_section(pa, pb, kept_a / wa, kept_b / wb, near);
  if (!section)
    return std::nullopt;
  EdgeBlendWindow window(*section, scale.tolerance);
  for (int f : band) {
    const bool in_a = label[std::size_t(f)] == pair.a;
    window.add_on_plane(g.centroid[std::size_t(f)], g.area[std::size_t(f)], in_a ? section->ray_a : section->ray_b,
                        in_a ? pa : pb);
  }
  const std::optional<EdgeBlendSample> sample = window.sample();
  if (!sample)
    return std::nullopt;
  const std::optional<EdgeBlendEstimate> estimate =
      best_edge_blend(*section, sample->points, sample->weights, sample->spread, reach, max_setback);
  if (!estimate || !(estimate->gain >= kMinBlendGain) || !(estimate->setback < max_setback))
    return std::nullopt;
  // The blend must stand off the sharp edge (along the bisector) at least as far as the fillet of the smallest
  // radius the growth keeps: tighter is the scanner's blur of a sharp edge.
  auto stand_off = [&](BlendForm form, double setback) {
    const double h = section->half_angle;
    return form == BlendForm::Fillet ? setback * (1 - std::sin(h)) / std::cos(h) : setback * std::cos(h);
  };
  if (!(stand_off(estimate->form, estimate->setback) >=
        stand_off(BlendForm::Fillet, scale.min_curvature_radius / std::tan(section->half_angle))))
    return std::nullopt;
  BlendCandidate c;
  c.blend.plane_a = pair.a;
  c.blend.plane_b = pair.b;
  c.blend.primitive = edge_blend_primitive(*section, estimate->form, estimate->setback);
  c.gain = estimate->gain;
  for (int f : band)
    if (in_edge_blend_sector(*section, estimate->setback, g.centroid[std::size_t(f)]))
      c.faces.push_back(f);
  return c;
}

} // namespace

std::vector<CarvedBlend> carve_edge_blends(const GrowingFaces& g, const FaceAdjacency& adj,
                                           const std::vector<Primitive>& primitive_of_region,
                                           const GrowingScale& scale, std::vector<int>& label, int threads)
{
  std::vector<CarvedBlend> out;
  if (!(scale.tolerance > 0) || label.empty() || label.size() != g.valid.size())
    return out;
  const std::vector<PlanePair> pairs = adjacent_plane_pairs(g, adj, primitive_of_region, label);
  // Each pair is scored alone, kept at its index: the same candidates on any thread count.
  std::vector<std::optional<BlendCandidate>> scored(pairs.size());
  std::vector<std::size_t> sizes(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i)
    sizes[i] = pairs[i].edges >= kMinBlendBorderEdges ? pairs[i].border.size() : 0;
  const int workers = std::max(1, std::min(resolve_thread_count(threads), int(pairs.size())));
  std::vector<FaceStamps> stamps(static_cast<std::size_t>(workers));
  for_each_largest_first(sizes, workers, [&](int worker, std::size_t i) {
    if (sizes[i] == 0)
      return;
    FaceStamps& own = stamps[std::size_t(worker)];
    if (own.stamp.empty())
      own.stamp.assign(label.size(), 0);
    scored[i] = blend_of_pair(g, adj, primitive_of_region, scale, label, pairs[i], own);
  });
  std::vector<BlendCandidate> candidates;
  for (std::optional<BlendCandidate>& c : scored)
    if (c)
      candidates.push_back(std::move(*c));
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const BlendCandidate& x, const BlendCandidate& y) { return x.gain > y.gain; });
  int next = std::max(int(primitive_of_region.size()), *std::max_element(label.begin(), label.end()) + 1);
  // Per plane region its faces and area before any carve, and the area blends took from it.
  std::vector<int> faces_of(primitive_of_region.size(), 0);
  std::vector<double> area_of(primitive_of_region.size(), 0.0), carved_of(primitive_of_region.size(), 0.0);
  for (std::size_t f = 0; f < label.size(); ++f)
    if (label[f] >= 0 && label[f] < int(faces_of.size())) {
      ++faces_of[std::size_t(label[f])];
      area_of[std::size_t(label[f])] += g.area[f];
    }
  for (BlendCandidate& c : candidates) {
    // Faces another blend took are no longer the planes'; each plane keeps a region's worth of its own.
    std::vector<int> faces;
    int from_a = 0;
    double area_a = 0, area_b = 0;
    for (int f : c.faces)
      if (label[std::size_t(f)] == c.blend.plane_a || label[std::size_t(f)] == c.blend.plane_b) {
        faces.push_back(f);
        const bool in_a = label[std::size_t(f)] == c.blend.plane_a;
        from_a += in_a ? 1 : 0;
        (in_a ? area_a : area_b) += g.area[std::size_t(f)];
      }
    const auto a = std::size_t(c.blend.plane_a), b = std::size_t(c.blend.plane_b);
    const int left_a = faces_of[a] - from_a;
    const int left_b = faces_of[b] - (int(faces.size()) - from_a);
    if (int(faces.size()) < scale.min_region_faces || left_a < scale.min_region_faces ||
        left_b < scale.min_region_faces)
      continue;
    // A plane's blends may take at most kMaxBlendShare of its region: its plane was fitted to the blends' faces
    // too, and a plane they bend is no footing for them (the bracket's 2.7 mm end walls, tilted 10-27 degrees by
    // the fillet and chamfer in their regions, read as 3 mm fillets of the bottom).
    if (carved_of[a] + area_a > kMaxBlendShare * area_of[a] || carved_of[b] + area_b > kMaxBlendShare * area_of[b])
      continue;
    carved_of[a] += area_a;
    carved_of[b] += area_b;
    faces_of[a] = left_a;
    faces_of[b] = left_b;
    for (int f : faces)
      label[std::size_t(f)] = next;
    c.blend.label = next++;
    out.push_back(c.blend);
  }
  return out;
}

} // namespace primitive_edit
