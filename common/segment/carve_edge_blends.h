// carve_edge_blends.h: a phase of segment_by_primitive_growing: the fillets and chamfers that the scan's roughness hid
// in the two planes they join become segments of their own.
//
// Input:  GrowingFaces, the FaceAdjacency, the regions' primitives (indexed by label), the GrowingScale, the labels
//         after relax_region_borders (labels without a primitive, components without a region, are left alone) and
//         the threads (parallel_for.h; <= 0: all; the result does not depend on them).
// Output: the labels of the carved faces changed to new ids beyond every label in use; per carved blend its id,
//         the two plane regions it joins and its primitive (edge_blend.h).
// Method: a blend that stands off its sharp edge by about the tolerance or less (a 1.5 mm fillet's arc lies 0.62 mm
//         inside the edge at its middle; a CT scan's tolerance is about 1 mm) is grown into its planes and split
//         between them at the bisector. For each pair of adjacent plane regions at kMinBlendAngleDeg or more: the
//         faces of both within the reach (kBlendReachTolerances tolerances) of their common line, walked from their
//         shared border and within its extent along the line, at most kBlendPoints of them evenly strided, are
//         scored by best_edge_blend (edge_blend_likelihood.h) with their own scatter: the RMS distance from their
//         plane of the faces beyond the largest setback (kBlendSetbackTolerances tolerances; edge_blend_window.h).
//         A blend is carved when
//         - its log-likelihood gain over the sharp edge is at least kMinBlendGain;
//         - its setback lies inside the searched range (one at the range's end is no blend of this edge: the
//           planes are off);
//         - it stands off the sharp edge at least as far as the fillet of radius min_curvature_radius (tighter is
//           the scanner's blur of a sharp edge, as the growth takes it).
//         Its faces are those of the two regions between its tangent lines; blends with larger gains first, a face
//         carved once, and a blend is not carved when it or either plane would be left with fewer than
//         min_region_faces faces, or when the blends of either plane would take more than kMaxBlendShare of its
//         region's area (the plane was fitted to their faces too: on the bracket scan's 2.7 mm end walls, tilted
//         10-27 degrees by their fillet and chamfer, the bottom's edge read as a 3 mm fillet).
// Limits: the likelihood counts the faces as independent, which a scan's roughness is not: waves as long as the
//         blend can read as one. On a corner with a 0.5 mm round under waves of 0.5 mm RMS over 4-8 mm (the test
//         WavyPlaneAndWallGiveTwoSegments) a 1.6 mm fillet is carved; on the bracket scan's 1.5 mm fillets under
//         waves of 0.33 mm over about 2 mm the evidence is no stronger (split along the edge in thirds, one third
//         often loses), so no test of it along the edge keeps the one and drops the other. The Segment filter's
//         CarveBlends turns the phase off.
// Cost:   O(border faces) to pair the regions, then per pair O(faces within the reach log) to walk and sort and
//         O(kBlendPoints) per setback tried (edge_blend_likelihood.h), the pairs divided by the threads.
#ifndef PRIMITIVE_EDIT_CARVE_EDGE_BLENDS_H
#define PRIMITIVE_EDIT_CARVE_EDGE_BLENDS_H

#include "common/base/primitive.h"
#include "common/mesh/face_adjacency.h"
#include "common/segment/grow_regions.h"
#include "common/segment/growing_faces.h"

#include <vector>

namespace primitive_edit {

constexpr double kMaxBlendShare = 1.0 / 3.0; // of a plane region's area its blends may take
constexpr int kMinBlendBorderEdges = 20; // shared edges below which two regions have no edge worth a blend

struct CarvedBlend
{
  int label = -1, plane_a = -1, plane_b = -1;
  Primitive primitive;
};

std::vector<CarvedBlend> carve_edge_blends(const GrowingFaces& g, const FaceAdjacency& adj,
                                           const std::vector<Primitive>& primitive_of_region,
                                           const GrowingScale& scale, std::vector<int>& label, int threads = 0);

} // namespace primitive_edit

#endif
