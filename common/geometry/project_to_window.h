// project_to_window.h: where a point appears in the window, as OpenGL's gluProject computes it.
//
// Input:  a point in object coordinates, clip_from_object = projection * modelview (column vectors), and the
//         viewport (x, y, width, height).
// Output: the window position (pixels, origin at the bottom-left, as plane_from_screen_line.h takes them), or
//         std::nullopt for a point at or behind the eye plane of a perspective view or a non-finite input.
// Cost:   O(1).
#ifndef PRIMITIVE_EDIT_PROJECT_TO_WINDOW_H
#define PRIMITIVE_EDIT_PROJECT_TO_WINDOW_H

#include <Eigen/Core>

#include <optional>

namespace primitive_edit {

std::optional<Eigen::Vector2d> project_to_window(const Eigen::Vector3d& p, const Eigen::Matrix4d& clip_from_object,
                                                 const Eigen::Vector4d& viewport);

} // namespace primitive_edit

#endif
