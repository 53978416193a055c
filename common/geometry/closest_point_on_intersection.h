// closest_point_on_intersection.h: the point nearest to p on the intersection curve of two primitives
// (the sharp edge between two snapped segments).
//
// Input:  two valid primitives a, b (see primitive.h), a point p, and max_distance: how far from p the
//         answer may lie.
// Output: true and `result` on both surfaces (to ~1e-11 of the coordinates' size) with result - p in
//         the span of the two surface normals there (a locally nearest point of the curve). False, with
//         `result` untouched, when an input is invalid or non-finite, the curve is farther than
//         max_distance from p, the surfaces are nearly tangent at the solution (normals less than
//         5 degrees apart: the edge is ill-defined there), or the iteration does not converge; the
//         caller then falls back to single-primitive projection.
// Method: Gauss-Newton on the constraints [f_a(x) = 0, f_b(x) = 0] (signed distances, whose gradients
//         are the normals of project_onto_primitive), minimising |x - p|: each step solves the
//         linearised constraints for the point nearest p, x <- p - J^T (J J^T)^-1 (f(x) + J (p - x)).
//         From x = p this is the min-norm Newton step; its fixed points are exactly the points of the
//         curve where x - p is orthogonal to the curve. Alternating projections would crawl near
//         tangency; this converges quadratically onto the curve and linearly (rate ~ curvature x
//         distance) along it.
// Cost:   O(1): at most 100 iterations of two projections.
#ifndef PRIMITIVE_EDIT_CLOSEST_POINT_ON_INTERSECTION_H
#define PRIMITIVE_EDIT_CLOSEST_POINT_ON_INTERSECTION_H

#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/iterate_to_nearest_solution.h"
#include "common/base/primitive.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace primitive_edit {

bool closest_point_on_intersection(const Primitive& a, const Primitive& b, const Eigen::Vector3d& p,
                                   double max_distance, Eigen::Vector3d& result);

} // namespace primitive_edit

#endif
