#include "common/geometry/closest_point_on_intersection.h"

namespace primitive_edit {

bool closest_point_on_intersection(const Primitive& a, const Primitive& b, const Eigen::Vector3d& p,
                                   double max_distance, Eigen::Vector3d& result)
{
  if (!primitive_is_valid(a) || !primitive_is_valid(b) || !p.allFinite() || !(max_distance > 0))
    return false;
  const double scale = 1.0 + p.norm();
  auto step = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
    const PrimitiveProjection pa = project_onto_primitive(a, x);
    const PrimitiveProjection pb = project_onto_primitive(b, x);
    const double c = pa.normal.dot(pb.normal);
    const double det = 1.0 - c * c;
    // Parallel normals: the linearised constraints have no solution (or a plane of them); a non-finite step
    // ends the iteration.
    if (!(det > 1e-12))
      return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    const Eigen::Vector3d d = p - x;
    const double ra = pa.signed_distance + pa.normal.dot(d);
    const double rb = pb.signed_distance + pb.normal.dot(d);
    // (J J^T)^-1 r with J J^T = [[1, c], [c, 1]].
    const double la = (ra - c * rb) / det;
    const double lb = (rb - c * ra) / det;
    return p - la * pa.normal - lb * pb.normal;
  };
  Eigen::Vector3d x;
  if (!iterate_to_nearest_solution(p, max_distance, step, x))
    return false;
  const PrimitiveProjection pa = project_onto_primitive(a, x);
  const PrimitiveProjection pb = project_onto_primitive(b, x);
  if (std::abs(pa.signed_distance) > 1e-11 * scale || std::abs(pb.signed_distance) > 1e-11 * scale)
    return false;
  if (pa.normal.cross(pb.normal).norm() < kMinSurfaceSine)
    return false;
  if ((x - p).norm() > max_distance)
    return false;
  result = x;
  return true;
}

} // namespace primitive_edit
