#include "common/pipeline/fit_segment.h"

namespace primitive_edit {

FitResult fit_segment(const SegmentSamples& samples, const std::optional<PrimitiveType>& type,
                      const AutoFitOptions& options)
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
