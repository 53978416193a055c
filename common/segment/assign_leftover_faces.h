// assign_leftover_faces.h: the fourth phase of segment_by_primitive_growing: every face no region holds
// goes to a region.
//
// Input:  GrowingFaces (its deleted faces stay -1), the FaceAdjacency, the regions' labels and primitives (after
//         dissolve_rough_regions.h), the tolerance.
// Output: label completed: the faces left over (blurred edges, fillets smaller than a seed patch, failed
//         seeds, dissolved regions) reached from a region get one; those of a component no region reaches
//         become one new label per component, numbered from the region count. Returns the label count.
// Method: a best-first flood from all regions' borders at once, cheapest (face_cost: nearest primitive)
//         first, so that a blurred edge between two planes is split at their bisector; then a breadth-first
//         walk per unreached component.
// Cost:   O(F log F).
#ifndef PRIMITIVE_EDIT_ASSIGN_LEFTOVER_FACES_H
#define PRIMITIVE_EDIT_ASSIGN_LEFTOVER_FACES_H

#include "common/segment/growing_faces.h"

#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace primitive_edit {

int assign_leftover_faces(const GrowingFaces& g, const FaceAdjacency& adj,
                          const std::vector<Primitive>& primitive_of_region, double tol, std::vector<int>& label);

} // namespace primitive_edit

#endif
