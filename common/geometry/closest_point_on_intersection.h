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
#include "common/base/primitive.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace primitive_edit {

inline bool closest_point_on_intersection(const Primitive& a, const Primitive& b, const Eigen::Vector3d& p,
                                          double max_distance, Eigen::Vector3d& result)
{
  if (!primitive_is_valid(a) || !primitive_is_valid(b) || !p.allFinite() || !(max_distance > 0))
    return false;
  // sin(5 degrees): below it the two surfaces are too close to tangent for a stable edge.
  constexpr double kMinSine = 0.08715574274765817;
  constexpr int kMaxIterations = 100;
  const double scale = 1.0 + p.norm();
  Eigen::Vector3d x = p;
  bool converged = false;
  for (int it = 0; it < kMaxIterations; ++it) {
    const PrimitiveProjection pa = project_onto_primitive(a, x);
    const PrimitiveProjection pb = project_onto_primitive(b, x);
    const double c = pa.normal.dot(pb.normal);
    const double det = 1.0 - c * c;
    // Parallel normals: the linearised constraints have no solution (or a plane of them).
    if (!(det > 1e-12))
      return false;
    const Eigen::Vector3d d = p - x;
    const double ra = pa.signed_distance + pa.normal.dot(d);
    const double rb = pb.signed_distance + pb.normal.dot(d);
    // (J J^T)^-1 r with J J^T = [[1, c], [c, 1]].
    const double la = (ra - c * rb) / det;
    const double lb = (rb - c * ra) / det;
    const Eigen::Vector3d next = p - la * pa.normal - lb * pb.normal;
    if (!next.allFinite())
      return false;
    const double step = (next - x).norm();
    x = next;
    if (step <= 1e-13 * scale) {
      converged = true;
      break;
    }
    // Far outside the allowed range: the answer cannot come back within max_distance in practice.
    if ((x - p).norm() > 10.0 * max_distance + scale)
      return false;
  }
  if (!converged)
    return false;
  const PrimitiveProjection pa = project_onto_primitive(a, x);
  const PrimitiveProjection pb = project_onto_primitive(b, x);
  if (std::abs(pa.signed_distance) > 1e-11 * scale || std::abs(pb.signed_distance) > 1e-11 * scale)
    return false;
  if (pa.normal.cross(pb.normal).norm() < kMinSine)
    return false;
  if ((x - p).norm() > max_distance)
    return false;
  result = x;
  return true;
}

} // namespace primitive_edit

#endif
