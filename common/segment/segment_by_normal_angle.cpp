#include "common/segment/segment_by_normal_angle.h"

namespace primitive_edit {

Status check_normal_angle_params(const SegmentByNormalAngleParams& params)
{
  char angle[96];
  std::snprintf(angle, sizeof angle, "between %g and %g degrees, not %g", kMinNormalAngleDeg, kMaxNormalAngleDeg,
                params.angle_deg);
  if (!(params.angle_deg > kMinNormalAngleDeg && params.angle_deg < kMaxNormalAngleDeg))
    return Status::failure("Angle must be " + std::string(angle) + ".");
  if (params.smoothing_iterations < -1 || params.smoothing_iterations > kMaxNormalSmoothingSteps)
    return Status::failure("Normal Smoothing Steps must be -1 (automatic) or 0 to " +
                           std::to_string(kMaxNormalSmoothingSteps) + ", not " +
                           std::to_string(params.smoothing_iterations) + ".");
  if (params.min_segment_faces < -1)
    return Status::failure("Min Segment Size must be -1 (automatic) or at least 0 faces, not " +
                           std::to_string(params.min_segment_faces) + ".");
  return Status::success();
}

namespace detail {

int min_segment_size(int min_segment_faces, int face_count, int noise_passes)
{
  if (min_segment_faces >= 0)
    return min_segment_faces;
  return std::max({kMinSegmentFacesFloor, int(double(face_count) * kMinSegmentShare),
                   kMinSegmentFacesPerPass * noise_passes});
}

} // namespace detail
} // namespace primitive_edit
