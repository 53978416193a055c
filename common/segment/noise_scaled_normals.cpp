#include "common/segment/noise_scaled_normals.h"

namespace primitive_edit {

int noise_smoothing_passes(double noise, double mean_face_area)
{
  if (!(noise > 0) || !(mean_face_area > 0) || !std::isfinite(noise / mean_face_area))
    return 0;
  const double passes = std::ceil(kNoisePassesPerSquaredRatio * noise * noise / mean_face_area);
  return passes <= kPaperSmoothingPasses ? 0 : int(std::min(passes, double(kMaxNoisePasses)));
}

double edge_turn_deg(double angle_deg, int passes)
{
  return angle_deg / std::sqrt(std::max(1.0, 0.75 * kPi * double(passes)));
}

double median_ring_plane_residual(const FaceCentroidsAndAreas& faces, const std::vector<Eigen::Vector3d>& raw,
                                  const FaceAdjacency& adj)
{
  std::vector<double> residual;
  for (std::size_t f = 0; f < raw.size(); ++f) {
    if (!(faces.area[f] > 0) || raw[f].isZero(0.0) || adj.offset[f] == adj.offset[f + 1])
      continue;
    double sum = 0;
    for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k)
      sum += std::pow((faces.centroid[std::size_t(adj.neighbour[std::size_t(k)])] - faces.centroid[f]).dot(raw[f]), 2);
    residual.push_back(std::sqrt(sum / double(adj.offset[f + 1] - adj.offset[f])));
  }
  if (residual.empty())
    return 0;
  std::nth_element(residual.begin(), residual.begin() + std::ptrdiff_t(residual.size() / 2), residual.end());
  return residual[residual.size() / 2];
}

} // namespace primitive_edit
