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

inline FitResult fit_segment(const SegmentSamples& samples, const std::optional<PrimitiveType>& type,
                             const AutoFitOptions& options = {})
{
  FitResult out;
  const Eigen::Index points = samples.points.rows();
  const PrimitiveType smallest = type.value_or(PrimitiveType::Plane);
  if (points < minimum_points_for(smallest)) {
    out.status = Status::failure(std::to_string(points) + " points; a " + primitive_type_name(smallest) +
                                 " needs at least " + std::to_string(minimum_points_for(smallest)));
    return out;
  }
  if (type) {
    out = fit_primitive(*type, samples.points, samples.normals, samples.weights, options.fit);
  } else {
    const AutoFitResult automatic = fit_primitive_auto(samples.points, samples.normals, samples.weights, options);
    out = automatic.best;
    out.status = automatic.status;
  }
  if (out.status.ok() && !primitive_is_valid(out.primitive))
    out.status = Status::failure("the fit gave an invalid " + std::string(primitive_type_name(out.primitive.type)));
  return out;
}

} // namespace primitive_edit

#endif
