#include "common/geometry/plane_from_screen_line.h"

namespace primitive_edit {

ScreenLinePlane plane_from_screen_line(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                       const Eigen::Matrix4d& modelview, const Eigen::Matrix4d& projection,
                                       const Eigen::Vector4d& viewport)
{
  ScreenLinePlane out;
  if (!a.allFinite() || !b.allFinite() || !modelview.allFinite() || !projection.allFinite() ||
      !viewport.allFinite()) {
    out.status = Status::failure("the screen line or the camera is not finite");
    return out;
  }
  if (!(viewport[2] > 0 && viewport[3] > 0)) {
    out.status = Status::failure("the viewport is empty");
    return out;
  }
  if ((b - a).norm() < 1e-6) {
    out.status = Status::failure("the line is too short: its end points coincide");
    return out;
  }
  const Eigen::Matrix4d clip_from_object = projection * modelview;
  Eigen::FullPivLU<Eigen::Matrix4d> lu(clip_from_object);
  if (!lu.isInvertible()) {
    out.status = Status::failure("the camera matrices are singular");
    return out;
  }
  const Eigen::Matrix4d object_from_clip = lu.inverse();

  // Window -> normalised device coordinates -> object coordinates; ndc_z = -1 near, +1 far.
  bool finite = true;
  auto unproject = [&](const Eigen::Vector2d& w, double ndc_z) {
    const Eigen::Vector4d ndc(2.0 * (w.x() - viewport[0]) / viewport[2] - 1.0,
                              2.0 * (w.y() - viewport[1]) / viewport[3] - 1.0, ndc_z, 1.0);
    const Eigen::Vector4d h = object_from_clip * ndc;
    if (!(std::abs(h.w()) > 1e-300)) {
      finite = false;
      return Eigen::Vector3d::Zero().eval();
    }
    return Eigen::Vector3d(h.head<3>() / h.w());
  };
  const Eigen::Vector3d a_near = unproject(a, -1.0), a_far = unproject(a, 1.0);
  const Eigen::Vector3d b_near = unproject(b, -1.0), b_far = unproject(b, 1.0);
  const Eigen::Vector3d along_line = (b_near - a_near) + (b_far - a_far);
  const Eigen::Vector3d along_view = (a_far - a_near) + (b_far - b_near);
  const Eigen::Vector3d normal = along_line.cross(along_view);
  const double length = normal.norm();
  // Relative test: parallel directions (a line along the view) leave a cross product of rounding size.
  if (!finite || !std::isfinite(length) || !(length > 1e-12 * along_line.norm() * along_view.norm())) {
    out.status = Status::failure("the line does not define a plane with this camera");
    return out;
  }
  out.point = 0.25 * (a_near + a_far + b_near + b_far);
  out.normal = normal / length;
  if (!out.point.allFinite() || !out.normal.allFinite()) {
    out.status = Status::failure("the line does not define a plane with this camera");
    return out;
  }
  return out;
}

} // namespace primitive_edit
