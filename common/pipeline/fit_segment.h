// fit_segment.h: the primitive of one segment (or of any set of faces), as "Primitive: Fit Segment",
// "Primitive: Snap Segment" and the edit tool's Fit compute it, so that all three give the same answer.
//
// Input:  the faces' samples (gather_segment_samples.h), the type to fit (std::nullopt: the type that
//         explains the points best) and the options of fit_primitive_auto; their `roughness` is the scan's
//         (estimate_surface_roughness.h), so that a segment of a rough scan is accepted as a primitive within
//         the scan's roughness; `fit` also applies to a given type.
// Output: FitResult. A failed status, saying why, when the faces have fewer points than the type needs
//         (minimum_points_for.h), when no type fits within the tolerance (automatic type: "free-form"), when
//         the fit of the given type fails, or when it gives an invalid primitive.
// Method: fit_primitive for a given type, fit_primitive_auto otherwise.
// Cost:   that of the fit.
#ifndef PRIMITIVE_EDIT_FIT_SEGMENT_H
#define PRIMITIVE_EDIT_FIT_SEGMENT_H

#include "common/fit/fit_primitive.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/minimum_points_for.h"
#include "common/mesh/gather_segment_samples.h"

#include <optional>
#include <string>

namespace primitive_edit {

FitResult fit_segment(const SegmentSamples& samples, const std::optional<PrimitiveType>& type,
                      const AutoFitOptions& options = {});

} // namespace primitive_edit

#endif
