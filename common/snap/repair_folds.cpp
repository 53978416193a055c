#include "common/snap/repair_folds.h"

namespace primitive_edit {

bool face_is_folded(const Eigen::Vector3d& reference, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                    const Eigen::Vector3d& p2)
{
  const double before = reference.norm();
  if (!std::isfinite(before) || before <= 0)
    return false;
  const Eigen::Vector3d after = (p1 - p0).cross(p2 - p0);
  return !(reference.dot(after) > 0) || !(after.norm() > 1e-3 * before);
}

} // namespace primitive_edit
