// dissolve_rough_regions.h: the third phase of segment_by_primitive_growing: regions that are only a crest
// or trough of their neighbours' roughness are undone.
//
// Input:  GrowingFaces, the merged GrowingRegions and the pairs of them that share an edge (both from
//         merge_regions.h) and the GrowingScale.
// Output: such regions lose their faces (label -1); returns how many were dissolved.
// Method: smallest region first: a region dissolves when, over kMergeShare of its area, its faces agree at twice
//         the tolerance with the primitive of a larger neighbour, face by face any of them
//         (share_near_neighbours): a crest parallel to one surface but beyond its tolerance, or a strip of the
//         blurred edge between two surfaces that its own primitive (a plane at 45 degrees, a wide cylinder)
//         explains no better than the two do. The flood of assign_leftover_faces.h then hands its faces to the
//         nearest primitives. Such strips are where the segmentation forked under perturbations of a few
//         nanometres (bench/bracket/README.md); measured there over perturbed copies, their dissolving gains
//         0.2 points on the bundled scan and 2.0 at 1M faces.
//         A region's larger neighbours are those it had before any dissolved: a region that dissolves earlier is
//         no larger than the one tested, so it is never one of them.
// Cost:   O(regions log regions + region pairs), plus O(kShareSampleCount * neighbours) per region; no pass over
//         the faces but to unlabel those of a dissolved region.
#ifndef PRIMITIVE_EDIT_DISSOLVE_ROUGH_REGIONS_H
#define PRIMITIVE_EDIT_DISSOLVE_ROUGH_REGIONS_H

#include "common/segment/merge_regions.h"

#include <algorithm>
#include <vector>

namespace primitive_edit {

// The share (by area) of kShareSampleCount evenly strided `faces` that agree (FaceAgreement at tol and angle)
// with the primitive of at least one of the `neighbours` regions.
double share_near_neighbours(const GrowingFaces& g, const GrowingRegions& regions, const std::vector<int>& faces,
                             const std::vector<int>& neighbours, double tol, double angle);

int dissolve_rough_regions(const GrowingFaces& g, const RegionPairs& adjacent, const GrowingScale& scale,
                           GrowingRegions& regions);

} // namespace primitive_edit

#endif
