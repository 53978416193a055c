#include "common/fit/check_fit_input.h"

namespace primitive_edit {

Status check_fit_input(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                       const Eigen::VectorXd& weights, int min_points)
{
  const Eigen::Index n = points.rows();
  const auto fail = Status::failure;
  if (normals.rows() != 0 && normals.rows() != n)
    return fail("normals must have as many rows as points (or none)");
  if (weights.size() != 0 && weights.size() != n)
    return fail("weights must have as many entries as points (or none)");
  if (!points.allFinite())
    return fail("points contain non-finite coordinates");
  if (normals.rows() != 0 && !normals.allFinite())
    return fail("normals contain non-finite values");
  Eigen::Index used = n;
  if (weights.size() != 0) {
    if (!weights.allFinite())
      return fail("weights contain non-finite values");
    if ((weights.array() < 0).any())
      return fail("weights must be non-negative");
    used = (weights.array() > 0).count();
  }
  if (used < min_points)
    return fail("too few points: " + std::to_string(used) + " with positive weight, need at least " +
                std::to_string(min_points));
  return Status::success();
}

} // namespace primitive_edit
