// iterate_to_nearest_solution.h: the Gauss-Newton loop shared by the sharp edge and corner points
// (closest_point_on_intersection.h, common_point_of_primitives.h).
//
// Input:  the query point p, max_distance (how far from p the answer may lie), and one step: the point
//         nearest p of the constraints linearised at x.
// Output: true and x, the iteration's fixed point, once a step moves it by at most 1e-13 of the coordinates'
//         size (scale = 1 + |p|). False when a step is not finite, x wanders farther than
//         10 max_distance + scale from p (it cannot come back within max_distance in practice), or 100 steps
//         do not converge. The caller checks that x lies on its surfaces and within max_distance.
//         kMinSurfaceSine: sin(5 degrees), below which surfaces meet too close to tangent for a stable point.
// Cost:   at most 100 steps.
#ifndef PRIMITIVE_EDIT_ITERATE_TO_NEAREST_SOLUTION_H
#define PRIMITIVE_EDIT_ITERATE_TO_NEAREST_SOLUTION_H

#include <Eigen/Core>

namespace primitive_edit {

constexpr double kMinSurfaceSine = 0.08715574274765817;

template <class Step>
bool iterate_to_nearest_solution(const Eigen::Vector3d& p, double max_distance, Step step, Eigen::Vector3d& x)
{
  constexpr int kMaxIterations = 100;
  const double scale = 1.0 + p.norm();
  x = p;
  for (int it = 0; it < kMaxIterations; ++it) {
    const Eigen::Vector3d next = step(x);
    if (!next.allFinite())
      return false;
    const double moved = (next - x).norm();
    x = next;
    if (moved <= 1e-13 * scale)
      return true;
    if ((x - p).norm() > 10.0 * max_distance + scale)
      return false;
  }
  return false;
}

} // namespace primitive_edit

#endif
