// edge_blend_window.h: the points about the edge of two planes that a blend's likelihood is judged on, and the
// noise's spread they show: gathered alike by the segmentation's carve (faces) and Fit All's found blends (samples).
//
// Input:  the EdgeSection (edge_blend.h) and the fit tolerance; then the points one at a time with their weights
//         (areas): a point of the blend, or a point of one of the planes with that plane and its ray in the section.
//         The caller has chosen them (near the edge, within its extent); the window does not filter them.
// Output: the reach and largest setback the likelihood takes (kBlendReachTolerances and kBlendSetbackTolerances
//         tolerances, edge_blend_likelihood.h); sample(): at most kBlendPoints of the points, evenly strided in the
//         order they came, their weights, and the spread: the weighted RMS distance from their own plane of the
//         planes' points beyond the largest setback and within the reach (there no blend searched can lie), at
//         least a tenth of the tolerance (exact data has no scatter; the floor keeps the likelihood from needing
//         every point on the profile). std::nullopt when the tolerance is not positive or no plane's point lies
//         in that range.
// Cost:   O(1) per point added, O(kBlendPoints) per sample.
#ifndef PRIMITIVE_EDIT_EDGE_BLEND_WINDOW_H
#define PRIMITIVE_EDIT_EDGE_BLEND_WINDOW_H

#include "common/base/primitive.h"
#include "common/geometry/edge_blend.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace primitive_edit {

struct EdgeBlendSample
{
  Eigen::MatrixX3d points;
  Eigen::VectorXd weights;
  double spread = 0;
};

class EdgeBlendWindow
{
public:
  EdgeBlendWindow(const EdgeSection& section, double tolerance);

  double reach() const { return reach_; }
  double max_setback() const { return max_setback_; }

  void add(const Eigen::Vector3d& p, double weight);
  // `ray` is the section's ray along `plane` (section.ray_a or ray_b).
  void add_on_plane(const Eigen::Vector3d& p, double weight, const Eigen::Vector3d& ray, const Primitive& plane);

  std::optional<EdgeBlendSample> sample() const;

private:
  EdgeSection section_;
  double tolerance_, reach_, max_setback_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<double> weights_;
  double scatter_sum2_ = 0, scatter_weight_ = 0;
};

} // namespace primitive_edit

#endif
