// dissolve_rough_regions.h: the third phase of segment_by_primitive_growing: regions that are only a crest
// or trough of a neighbour's roughness are undone.
//
// Input:  GrowingFaces, the FaceAdjacency, the merged GrowingRegions (merge_regions.h) and the GrowingScale.
// Output: such regions lose their faces (label -1); returns how many were dissolved.
// Method: smallest region first: a region dissolves when it agrees with a larger neighbour's primitive at
//         twice the tolerance over kMergeShare of its area (sampled_share): parallel to that surface but beyond
//         its tolerance. The flood of assign_leftover_faces.h then hands its faces to the nearest primitives.
// Cost:   O(F) for the neighbours, plus O(kShareSampleCount) per neighbour tested.
#ifndef PRIMITIVE_EDIT_DISSOLVE_ROUGH_REGIONS_H
#define PRIMITIVE_EDIT_DISSOLVE_ROUGH_REGIONS_H

#include "common/segment/merge_regions.h"

#include <algorithm>
#include <vector>

namespace primitive_edit {

int dissolve_rough_regions(const GrowingFaces& g, const FaceAdjacency& adj, const GrowingScale& scale,
                           GrowingRegions& regions);

} // namespace primitive_edit

#endif
