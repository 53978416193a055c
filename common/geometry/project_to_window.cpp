#include "common/geometry/project_to_window.h"

namespace primitive_edit {

std::optional<Eigen::Vector2d> project_to_window(const Eigen::Vector3d& p, const Eigen::Matrix4d& clip_from_object,
                                                 const Eigen::Vector4d& viewport)
{
  const Eigen::Vector4d c = clip_from_object * Eigen::Vector4d(p.x(), p.y(), p.z(), 1.0);
  if (!(c.w() > 0) || !c.allFinite())
    return std::nullopt;
  const Eigen::Vector2d ndc(c.x() / c.w(), c.y() / c.w());
  return Eigen::Vector2d(viewport[0] + 0.5 * (ndc.x() + 1.0) * viewport[2],
                         viewport[1] + 0.5 * (ndc.y() + 1.0) * viewport[3]);
}

} // namespace primitive_edit
