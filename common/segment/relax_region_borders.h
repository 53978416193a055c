// relax_region_borders.h: the last phase of segment_by_primitive_growing: border faces move to the
// neighbouring region whose primitive explains them best.
//
// Input:  GrowingFaces, the FaceAdjacency, the regions' primitives, the tolerance and the labels (labels at or
//         beyond the region count, components without a region, are left alone); the threads that find the
//         faces at borders (parallel_for.h; <= 0: all).
// Output: label updated; returns the faces moved.
// Method: passes over all faces (at most kRelaxPasses, until none moves): a face goes to the adjacent region
//         with the smallest face_cost, if smaller than its own. Growth within the tolerance lets a region
//         take the tangent start of the next surface (a plane the start of a fillet); the scan's ground truth
//         is the nearest surface.
// Cost:   O(F) on the threads to find the faces at borders; the passes look only at those and at the faces next
//         to a move (and skim a byte per face).
#ifndef PRIMITIVE_EDIT_RELAX_REGION_BORDERS_H
#define PRIMITIVE_EDIT_RELAX_REGION_BORDERS_H

#include "common/base/huge_page_vector.h"
#include "common/segment/growing_faces.h"

#include <vector>

namespace primitive_edit {

constexpr int kRelaxPasses = 20;

// The region face f should have: of its own and its neighbours' regions, the first whose primitive explains f
// at the smallest face_cost. f's own when f has no region, one beyond the regions, or is not valid.
int best_region_for_face(const GrowingFaces& g, const FaceAdjacency& adj,
                         const std::vector<Primitive>& primitive_of_region, double tol,
                         const std::vector<int>& label, int f);

int relax_region_borders(const GrowingFaces& g, const FaceAdjacency& adj,
                         const std::vector<Primitive>& primitive_of_region, double tol, std::vector<int>& label,
                         int threads = 0);

} // namespace primitive_edit

#endif
