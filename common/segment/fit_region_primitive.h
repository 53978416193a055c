// fit_region_primitive.h: a primitive for a set of faces, accepted only when the faces agree with it.
//
// Input:  GrowingFaces (growing_faces.h), the faces, an optional start primitive, the distance tolerance,
//         the normal angle (radians), the share of the faces' area that must agree (FaceAgreement) and the
//         threads for fit_primitive_auto's candidate types (the result does not depend on them).
// Output: the primitive, or std::nullopt when none is accepted.
// Method: on at most kFitSampleCount evenly strided faces (centroid, smoothed normal, area): with a start,
//         the start refined (refine_primitive, 10 iterations), a cone that no longer tapers by the tolerance
//         over the faces as its cylinder (reduce_degenerate_cone.h); without, a plane first, then
//         fit_primitive_auto at half the tolerance. The faces' agreeing share decides.
// Cost:   O(kFitSampleCount) per iteration of the fits, plus O(faces) for the share.
#ifndef PRIMITIVE_EDIT_FIT_REGION_PRIMITIVE_H
#define PRIMITIVE_EDIT_FIT_REGION_PRIMITIVE_H

#include "common/fit/fit_plane.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/reduce_degenerate_cone.h"
#include "common/fit/refine_primitive.h"
#include "common/segment/growing_faces.h"

#include <optional>
#include <vector>

namespace primitive_edit {

constexpr int kFitSampleCount = 600; // faces a region's fit uses at most

std::optional<Primitive> fit_region_primitive(const GrowingFaces& g, const std::vector<int>& faces,
                                              const Primitive* start, double tol, double angle, double share,
                                              int threads = 1);

} // namespace primitive_edit

#endif
