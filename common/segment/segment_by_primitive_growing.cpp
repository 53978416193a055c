#include "common/segment/segment_by_primitive_growing.h"

namespace primitive_edit {

Status check_primitive_growing_params(const SegmentByPrimitiveGrowingParams& params)
{
  auto number = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return std::string(text);
  };
  if (!std::isfinite(params.tolerance) || params.tolerance < 0)
    return Status::failure("Tolerance must be 0 (automatic) or positive, not " + number(params.tolerance) + ".");
  if (!(params.normal_angle_deg >= kMinGrowingNormalAngleDeg && params.normal_angle_deg <= kMaxGrowingNormalAngleDeg))
    return Status::failure("Normal Angle must be between " + number(kMinGrowingNormalAngleDeg) + " and " +
                           number(kMaxGrowingNormalAngleDeg) + " degrees, not " + number(params.normal_angle_deg) + ".");
  if (params.seed_patch_faces < kMinSeedPatchFaces)
    return Status::failure("Seed Patch Size must be at least " + std::to_string(kMinSeedPatchFaces) + " faces, not " +
                           std::to_string(params.seed_patch_faces) + ".");
  if (params.smoothing_iterations < 0 || params.smoothing_iterations > kMaxSmoothingIterations)
    return Status::failure("Normal Smoothing Steps must be 0 to " + std::to_string(kMaxSmoothingIterations) +
                           ", not " + std::to_string(params.smoothing_iterations) + ".");
  return Status::success();
}

namespace grow_detail {

double mean_edge_length(const GrowingFaces& g)
{
  double sum = 0;
  int valid_faces = 0;
  for (std::size_t f = 0; f < g.valid.size(); ++f)
    if (g.valid[f]) {
      sum += std::sqrt(4.0 * g.area[f] / std::sqrt(3.0));
      ++valid_faces;
    }
  return valid_faces ? sum / valid_faces : 0.0;
}

} // namespace grow_detail
} // namespace primitive_edit
