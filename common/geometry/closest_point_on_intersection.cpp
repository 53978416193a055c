#include "common/geometry/closest_point_on_intersection.h"

namespace primitive_edit {

bool closest_point_on_intersection(const Primitive& a, const Primitive& b, const Eigen::Vector3d& p,
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
