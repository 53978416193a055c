// closest_point_on_triangle.h: the point of a triangle nearest to a point.
//
// Input:  p and the corners a, b, c (Eigen::Vector3d).
// Output: the nearest point of the solid triangle abc. The triangle must have a nonzero area (a degenerate
//         one can divide by zero: callers skip or handle such faces).
// Method: Voronoi regions of the corners, edges and face (Ericson, Real-Time Collision Detection, 5.1.5).
// Cost:   O(1).
#ifndef PRIMITIVE_EDIT_CLOSEST_POINT_ON_TRIANGLE_H
#define PRIMITIVE_EDIT_CLOSEST_POINT_ON_TRIANGLE_H

#include <Eigen/Core>

namespace primitive_edit {

Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

} // namespace primitive_edit

#endif
