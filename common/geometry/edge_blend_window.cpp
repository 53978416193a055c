#include "common/geometry/edge_blend_window.h"

#include "common/geometry/edge_blend_likelihood.h"

#include <algorithm>
#include <cmath>

namespace primitive_edit {

EdgeBlendWindow::EdgeBlendWindow(const EdgeSection& section, double tolerance)
    : section_(section), tolerance_(tolerance), reach_(kBlendReachTolerances * tolerance),
      max_setback_(kBlendSetbackTolerances * tolerance)
{
}

void EdgeBlendWindow::add(const Eigen::Vector3d& p, double weight)
{
  points_.push_back(p);
  weights_.push_back(weight);
}

void EdgeBlendWindow::add_on_plane(const Eigen::Vector3d& p, double weight, const Eigen::Vector3d& ray,
                                   const Primitive& plane)
{
  const double along = distance_along(section_, ray, p);
  if (along > max_setback_ && along < reach_) {
    const double d = (p - plane.origin).dot(plane.axis);
    scatter_sum2_ += weight * d * d;
    scatter_weight_ += weight;
  }
  add(p, weight);
}

std::optional<EdgeBlendSample> EdgeBlendWindow::sample() const
{
  if (!(tolerance_ > 0) || !(scatter_weight_ > 0))
    return std::nullopt;
  const std::size_t count = std::min(points_.size(), std::size_t(kBlendPoints));
  EdgeBlendSample s;
  s.points.resize(Eigen::Index(count), 3);
  s.weights.resize(Eigen::Index(count));
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t k = i * points_.size() / count;
    s.points.row(Eigen::Index(i)) = points_[k].transpose();
    s.weights[Eigen::Index(i)] = weights_[k];
  }
  s.spread = std::max(std::sqrt(scatter_sum2_ / scatter_weight_), 0.1 * tolerance_);
  return s;
}

} // namespace primitive_edit
