// plane_from_screen_line.h: the cutting plane of a line drawn on screen: the plane through the line and the
// viewing direction (the paper's manual split, Fig. 4b), in the coordinates the modelview matrix maps from.
//
// Input:  the line's two end points a, b in window coordinates (OpenGL convention: pixels, origin at the
//         bottom-left of the window), the modelview and projection matrices (column vectors, as OpenGL's
//         glGetDoublev gives them once mapped to Eigen's column-major storage) and the viewport
//         (x, y, width, height). Perspective and orthographic projections both work.
// Output: ScreenLinePlane: a point of the plane and its unit normal; every point that projects onto the line
//         (at any depth) lies on the plane. A failed status when the end points coincide (closer
//         than 1e-6 pixels), any input is not finite, the viewport is empty or projection * modelview is
//         singular.
// Method: each end point is un-projected at the near and far clipping depths; the four points are coplanar
//         (both rays start at the eye, or are parallel for an orthographic view); the normal is the cross
//         product of the along-line and the along-view directions.
// Cost:   O(1) (one 4 x 4 inversion).
#ifndef PRIMITIVE_EDIT_PLANE_FROM_SCREEN_LINE_H
#define PRIMITIVE_EDIT_PLANE_FROM_SCREEN_LINE_H

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <string>

#include "common/base/status.h"

namespace primitive_edit {

struct ScreenLinePlane
{
  Status status;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

ScreenLinePlane plane_from_screen_line(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                       const Eigen::Matrix4d& modelview, const Eigen::Matrix4d& projection,
                                       const Eigen::Vector4d& viewport);

} // namespace primitive_edit

#endif
