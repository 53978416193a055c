// grow_regions.h: the first phase of segment_by_primitive_growing: regions grown from seeds, each with
// the primitive its faces agree with.
//
// Input:  GrowingFaces (growing_faces.h), the FaceAdjacency and GrowingScale: the distance tolerance and
//         normal angle of FaceAgreement, the faces of a seed patch, the fewest faces a region keeps and the
//         smallest radius of curvature a region's primitive may have (smaller: an edge rounded by the
//         scanner's blur, not a CAD surface).
// Output: GrowingRegions: label (region of each face, -1 for none), and per region its primitive and faces.
// Method: seeds in order of flatness (the smoothed normal's variation over the 1-ring, flattest first).
//         From each unassigned seed: a breadth-first patch of seed_patch_faces faces, fitted
//         (fit_region_primitive, 90% must agree); a patch that fits nothing marks its faces as failed seeds.
//         The region grows breadth-first over unassigned faces that agree with the primitive, refitted each
//         time the region has grown by half. When growth stops, a primitive of another type fitted on the
//         region and kBandRings rings around it (95% must agree) replaces it and growth resumes (a plane
//         patch that is part of a large cylinder), twice at most. Regions smaller than min_region_faces or
//         curved more tightly than min_curvature_radius are undone, their faces marked failed.
// Cost:   O(F) for the seed order (a radix sort); growth visits each face O(1) times per refit of its region,
//         and refits happen at geometric size steps on at most kFitSampleCount faces.
#ifndef PRIMITIVE_EDIT_GROW_REGIONS_H
#define PRIMITIVE_EDIT_GROW_REGIONS_H

#include "common/base/huge_page_vector.h"
#include "common/base/progress.h"
#include "common/base/sort_by_key.h"
#include "common/segment/fit_region_primitive.h"
#include "common/segment/growing_faces.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace primitive_edit {

struct GrowingScale
{
  double tolerance = 0;            // mesh units
  double angle = 0;                // radians
  int seed_patch_faces = 60;
  int min_region_faces = 60;
  double min_curvature_radius = 0; // mesh units
};

struct GrowingRegions
{
  std::vector<int> label;                    // region of each face, -1: none
  std::vector<Primitive> primitive;          // per region
  std::vector<std::vector<int>> faces;       // per region
};

constexpr int kBandRings = 3; // rings around a stopped region that a type change must explain

// Visit stamps shared by the breadth-first walks, so that none needs clearing.
struct FaceStamps
{
  std::vector<int> stamp;
  int mark = 0;
};

// Breadth-first patch of at most max_faces faces from `starts` over faces for which usable(f) holds.
template <class Usable>
void bfs_patch(const FaceAdjacency& adj, const std::vector<int>& starts, std::size_t max_faces, Usable usable,
               FaceStamps& stamps, std::vector<int>& patch)
{
  const int mark = ++stamps.mark;
  std::vector<int>& stamp = stamps.stamp;
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

inline std::vector<int> seed_order(const GrowingFaces& g, const FaceAdjacency& adj)
{
  const std::size_t n = g.valid.size();
  std::vector<double> variation = huge_page_vector(n, std::numeric_limits<double>::infinity());
  std::vector<int> order;
  reserve_on_huge_pages(order, n);
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
  sort_by_key(order, [&](int f) { return variation[std::size_t(f)]; });
  return order;
}

namespace grow_detail {

// Grows region `id` breadth-first (after a refit, faces rejected before may agree) over unassigned faces that
// agree with prim, refitting it each time the region has grown by half since the last fit. Returns when a walk
// ends without that growth. Each walk starts from the region's faces that still had an unassigned neighbour
// after the walk before, in region order, so it adds the same faces in the same order as a walk from the whole
// region, without rescanning its inside (the region's labels only grow, so a face once closed stays closed).
inline void grow_while_agreeing(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale, int id,
                                Primitive& prim, std::size_t& fitted_size, std::vector<int>& region,
                                std::vector<int>& label, FaceStamps& stamps, std::vector<int>& queue)
{
  auto unassigned = [&](int f) { return g.valid[std::size_t(f)] && label[std::size_t(f)] < 0; };
  const FaceAgreement agrees(scale.tolerance, scale.angle);
  std::vector<int> open_faces = region;
  for (;;) {
    const int grow_mark = ++stamps.mark;
    queue.swap(open_faces);
    open_faces.clear();
    std::size_t head = 0;
    while (head < queue.size()) {
      const int f = queue[head++];
      bool open = false;
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int h = adj.neighbour[std::size_t(k)];
        if (!unassigned(h))
          continue;
        if (stamps.stamp[std::size_t(h)] != grow_mark) {
          stamps.stamp[std::size_t(h)] = grow_mark;
          if (agrees(g, prim, h)) {
            label[std::size_t(h)] = id;
            region.push_back(h);
            queue.push_back(h);
            continue;
          }
        }
        open = true; // h was rejected, now or earlier in this walk
      }
      if (open)
        open_faces.push_back(f);
      if (region.size() >= fitted_size + fitted_size / 2)
        break;
    }
    if (region.size() < fitted_size + fitted_size / 2)
      return;
    open_faces.insert(open_faces.end(), queue.begin() + std::ptrdiff_t(head), queue.end()); // not walked from yet
    fitted_size = region.size();
    if (const std::optional<Primitive> refined =
            fit_region_primitive(g, region, &prim, scale.tolerance, scale.angle, 0.9))
      prim = *refined;
  }
}

// A primitive of another type than `prim` that the stopped region and kBandRings rings of unassigned faces
// around it agree with (95%), or nullopt.
inline std::optional<Primitive> wider_type(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                                           int id, const Primitive& prim, const std::vector<int>& region,
                                           const std::vector<int>& label, FaceStamps& stamps, std::vector<int>& band)
{
  bfs_patch(adj, region, region.size() + region.size() / 2, [&](int f) { return label[std::size_t(f)] == id; },
            stamps, band);
  const int mark = stamps.mark;
  const std::size_t inner = band.size();
  for (int ring = 0, begin = 0; ring < kBandRings; ++ring) {
    const int end = int(band.size());
    for (int i = begin; i < end; ++i) {
      const int f = band[std::size_t(i)];
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int h = adj.neighbour[std::size_t(k)];
        if (stamps.stamp[std::size_t(h)] != mark && g.valid[std::size_t(h)] && label[std::size_t(h)] < 0) {
          stamps.stamp[std::size_t(h)] = mark;
          band.push_back(h);
        }
      }
    }
    begin = end;
  }
  if (band.size() == inner)
    return std::nullopt;
  std::optional<Primitive> wider = fit_region_primitive(g, band, nullptr, scale.tolerance, scale.angle, 0.95);
  if (!wider || wider->type == prim.type)
    return std::nullopt;
  return wider;
}

} // namespace grow_detail

inline GrowingRegions grow_regions(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                                   const Progress& progress = {})
{
  using namespace grow_detail;
  const std::size_t face_count = g.valid.size();
  GrowingRegions out;
  assign_on_huge_pages(out.label, face_count, -1);
  std::vector<int>& label = out.label;
  std::vector<char> failed = huge_page_vector(face_count, char(0)); // faces no seed should be tried from
  FaceStamps stamps;
  assign_on_huge_pages(stamps.stamp, face_count, 0);
  const std::vector<int> order = scale.tolerance > 0 ? seed_order(g, adj) : std::vector<int>();
  std::vector<int> patch, region, queue, band;
  auto unassigned = [&](int f) { return g.valid[std::size_t(f)] && label[std::size_t(f)] < 0; };
  std::size_t processed = 0;
  for (int seed : order) {
    ++processed;
    if ((processed & 0x3FFF) == 0)
      report_progress(progress, int(100.0 * double(processed) / double(order.size())), "Growing regions");
    if (!unassigned(seed) || failed[std::size_t(seed)])
      continue;
    bfs_patch(adj, {seed}, std::size_t(scale.seed_patch_faces), unassigned, stamps, patch);
    std::optional<Primitive> prim;
    if (int(patch.size()) >= scale.seed_patch_faces / 2)
      prim = fit_region_primitive(g, patch, nullptr, scale.tolerance, scale.angle, 0.9);
    if (!prim) {
      for (int f : patch)
        failed[std::size_t(f)] = 1;
      continue;
    }
    const int id = int(out.primitive.size());
    region.assign(1, seed);
    label[std::size_t(seed)] = id;
    std::size_t fitted_size = patch.size();
    for (int type_changes = 0;; ++type_changes) {
      grow_while_agreeing(g, adj, scale, id, *prim, fitted_size, region, label, stamps, queue);
      if (type_changes >= 2 || int(region.size()) < scale.min_region_faces)
        break;
      const std::optional<Primitive> wider = wider_type(g, adj, scale, id, *prim, region, label, stamps, band);
      if (!wider)
        break;
      prim = wider;
    }
    if (int(region.size()) < scale.min_region_faces || curvature_radius(*prim) < scale.min_curvature_radius) {
      for (int f : region) {
        label[std::size_t(f)] = -1;
        failed[std::size_t(f)] = 1;
      }
      continue;
    }
    out.primitive.push_back(*prim);
    out.faces.push_back(region);
  }
  return out;
}

} // namespace primitive_edit

#endif
