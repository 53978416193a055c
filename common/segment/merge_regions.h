// merge_regions.h: the second phase of segment_by_primitive_growing: adjacent grown regions that are one
// surface become one region.
//
// Input:  GrowingFaces, the FaceAdjacency, the GrowingRegions of grow_regions.h, its GrowingScale and the threads
//         (parallel_for.h; <= 0: all).
// Output: the regions merged in place: a merged region keeps the smaller id and the union's primitive, the
//         other keeps no faces; label follows. Returns the pairs of merged regions that share an edge (the grown
//         regions' borders mapped to the regions they went into), for the phases after.
// Method: pairs of adjacent regions, longest shared border first, in rounds until nothing merges (after the
//         first round, only pairs with a region that merged in the round before). A pair merges when one
//         primitive agrees with each region over at least kMergeShare of its area (merged_primitive): the
//         share is measured per region, so that a small region of another surface is not outvoted, and
//         against the scan's own roughness: faces of one rough surface miss the tests here and there, those
//         of a surface meeting it at an edge almost all miss. Candidates are each region's primitive refined
//         on the union, so the types may differ (a piece of a wavy plane that growth fitted with a torus
//         joins the plane), except that a torus is tried only for two tori: it has the freedom to also fit a
//         fillet with the faces it joins. A candidate is taken in its simplest form within the tolerance: a cone
//         that no longer tapers as its cylinder (reduce_degenerate_cone.h), a sphere or cylinder that no longer
//         sags as a plane. The candidate whose worse region agrees most wins.
//         The pairs are tested kMergeWindowPerThread per thread at once (the tests only read the regions), then
//         merged in border order; a pair whose region a merge of its window changed is tested again, so the
//         merges are those of testing one pair after the other on any thread count.
// Cost:   O(E log E) for the borders; per round O(region adjacencies * (kFitSampleCount + kShareSampleCount)),
//         divided by the threads but for the pairs tested again; a test reads the two regions' faces in place,
//         and only a merge appends one region's faces to the other's.
#ifndef PRIMITIVE_EDIT_MERGE_REGIONS_H
#define PRIMITIVE_EDIT_MERGE_REGIONS_H

#include "common/base/find_root.h"
#include "common/base/parallel_for.h"
#include "common/segment/fit_region_primitive.h"
#include "common/segment/grow_regions.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace primitive_edit {

constexpr double kMergeShare = 0.5; // share of each region that must agree with the union's primitive
// Pairs tested at once per thread: fewer leave a thread idle behind a long test, more test stale pairs.
constexpr std::size_t kMergeWindowPerThread = 4;

std::optional<Primitive> merged_primitive(const GrowingFaces& g, const std::vector<int>& fa, const Primitive& pa,
                                          const std::vector<int>& fb, const Primitive& pb,
                                          const GrowingScale& scale);

namespace merge_detail {

// (-shared edges, a, b) for every pair of adjacent regions a < b, longest border first.
std::vector<std::tuple<int, int, int>> region_borders(const FaceAdjacency& adj, const std::vector<int>& label);

} // namespace merge_detail

// Pairs (a, b), a < b, of regions that share an edge, sorted.
using RegionPairs = std::vector<std::pair<int, int>>;

RegionPairs merge_regions(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                          GrowingRegions& regions, int threads = 0);

} // namespace primitive_edit

#endif
