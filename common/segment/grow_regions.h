// grow_regions.h: the first phase of segment_by_primitive_growing: regions grown from seeds, each with
// the primitive its faces agree with.
//
// Input:  GrowingFaces (growing_faces.h), the FaceAdjacency and GrowingScale: the distance tolerance and
//         normal angle of FaceAgreement, the faces of a seed patch, the fewest faces a region keeps and the
//         smallest radius of curvature a region's primitive may have (smaller: an edge rounded by the
//         scanner's blur, not a CAD surface); the threads for the seed order and a type change's fits (the
//         result does not depend on them).
// Output: GrowingRegions: label (region of each face, -1 for none), and per region its primitive and faces.
// Method: seeds in order of flatness (seed_queue.h: the smoothed normal's variation over the 1-ring, flattest
//         first).
//         From each unassigned seed: a breadth-first patch of seed_patch_faces faces, fitted
//         (fit_region_primitive, 90% must agree); a patch that fits nothing marks its faces as failed seeds.
//         The region grows breadth-first over unassigned faces that agree with the primitive, refitted each
//         time the region has grown by half. When growth stops, a primitive of another type fitted on the
//         region and kBandRings rings around it (95% must agree), and fitting the stopped region itself no
//         worse (sampled_rms), replaces it and growth resumes (a plane patch that is part of a large
//         cylinder), twice at most. Regions smaller than min_region_faces or curved more tightly than
//         min_curvature_radius are undone, their faces marked failed.
// Cost:   O(F) for the seed order (sorted bucket by bucket); growth visits each face O(1) times per refit of its
//         region, and refits happen at geometric size steps on at most kFitSampleCount faces.
#ifndef PRIMITIVE_EDIT_GROW_REGIONS_H
#define PRIMITIVE_EDIT_GROW_REGIONS_H

#include "common/base/huge_page_vector.h"
#include "common/base/progress.h"
#include "common/segment/fit_region_primitive.h"
#include "common/segment/growing_faces.h"
#include "common/segment/seed_queue.h"

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

namespace grow_detail {

// Grows region `id` breadth-first (after a refit, faces rejected before may agree) over unassigned faces that
// agree with prim, refitting it each time the region has grown by half since the last fit. Returns when a walk
// ends without that growth, with open_faces: the region's faces that have an unassigned neighbour, in region
// order. Each walk starts from the open faces of the walk before, so it adds the same faces in the same order as
// a walk from the whole region, without rescanning its inside (the region's labels only grow, so a face once
// closed stays closed).
void grow_while_agreeing(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale, int id,
                         Primitive& prim, std::size_t& fitted_size, std::vector<int>& region,
                         std::vector<int>& label, FaceStamps& stamps, std::vector<int>& queue,
                         std::vector<int>& open_faces);

// A primitive of another type than `prim` that the stopped region and kBandRings rings of unassigned faces
// around it agree with (95%) and that fits the stopped region no worse than prim (sampled_rms), or nullopt. The
// band is the region followed by its rings, the first ring walked from the region's open faces
// (grow_while_agreeing) rather than from all of its faces. The candidate types are fitted on `threads` (the
// result does not depend on them).
std::optional<Primitive> wider_type(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                                    const Primitive& prim, const std::vector<int>& region,
                                    const std::vector<int>& open_faces, const std::vector<int>& label,
                                    FaceStamps& stamps, std::vector<int>& band, int threads);

} // namespace grow_detail

GrowingRegions grow_regions(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                            const Progress& progress = {}, int threads = 0);

} // namespace primitive_edit

#endif
