#include "common/geometry/primitive_wireframe.h"

namespace primitive_edit {

namespace wireframe_detail {

AxialExtent axial_extent(const Eigen::MatrixX3d& points, const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& d, double size)
{
  AxialExtent e{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                Eigen::Vector3d::Zero()};
  int count = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d q = points.row(i).transpose();
    if (!q.allFinite())
      continue;
    const double h = (q - origin).dot(d);
    e.lo = std::min(e.lo, h);
    e.hi = std::max(e.hi, h);
    e.centroid += q;
    ++count;
  }
  if (count == 0)
    return {-size, size, origin};
  e.centroid /= count;
  return e;
}

void plane_grid(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::Vector3d& d,
                const Eigen::Vector3d& u, const Eigen::Vector3d& v, const Eigen::Vector3d& centroid,
                double size, Lines& lines)
{
  const Eigen::Vector3d c = centroid - (centroid - p.origin).dot(d) * d;
  double reach = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d q = points.row(i).transpose();
    if (q.allFinite())
      reach = std::max({reach, std::abs((q - c).dot(u)), std::abs((q - c).dot(v))});
  }
  if (!(reach > 0))
    reach = size;
  for (int i = 0; i <= 5; ++i) {
    const double t = -reach + 2.0 * reach * i / 5;
    lines.line(c + t * u - reach * v, c + t * u + reach * v);
    lines.line(c - reach * u + t * v, c + reach * u + t * v);
  }
}

} // namespace wireframe_detail

Eigen::MatrixX3d primitive_wireframe(const Primitive& p, const Eigen::MatrixX3d& points, int pieces)
{
  using namespace wireframe_detail;
  if (!primitive_is_valid(p))
    return Eigen::MatrixX3d(0, 3);
  Lines lines{std::clamp(pieces, 8, 256), {}};
  const Eigen::Vector3d d = p.type == PrimitiveType::Sphere ? Eigen::Vector3d::UnitZ() : p.axis.normalized();
  const Eigen::Vector3d u = any_orthogonal(d);
  const Eigen::Vector3d v = d.cross(u);
  const double size = p.radius > 0 ? p.radius : 1.0;
  const AxialExtent h = axial_extent(points, p.origin, d, size);

  switch (p.type) {
  case PrimitiveType::Plane:
    plane_grid(p, points, d, u, v, h.centroid, size, lines);
    break;
  case PrimitiveType::Sphere:
    lines.circle(p.origin, u, v, p.radius);
    lines.circle(p.origin, u, d, p.radius);
    lines.circle(p.origin, v, d, p.radius);
    for (double s : {-0.5, 0.5})
      lines.circle(p.origin + s * p.radius * d, u, v, p.radius * std::sqrt(0.75));
    break;
  case PrimitiveType::Cylinder:
    for (int i = 0; i <= 4; ++i)
      lines.circle(p.origin + (h.lo + (h.hi - h.lo) * i / 4) * d, u, v, p.radius);
    for (int i = 0; i < 12; ++i) {
      const Eigen::Vector3d r = p.radius * Lines::around(i, 12, u, v);
      lines.line(p.origin + h.lo * d + r, p.origin + h.hi * d + r);
    }
    break;
  case PrimitiveType::Cone: {
    // Only the nappe the axis points into exists.
    const double lo = std::max(h.lo, 0.0), hi = std::max(h.hi, lo);
    const double slope = std::tan(p.half_angle);
    for (int i = 0; i <= 4; ++i) {
      const double z = lo + (hi - lo) * i / 4;
      lines.circle(p.origin + z * d, u, v, z * slope);
    }
    for (int i = 0; i < 12; ++i) {
      const Eigen::Vector3d dir = Lines::around(i, 12, u, v);
      lines.line(p.origin + lo * (d + slope * dir), p.origin + hi * (d + slope * dir));
    }
    break;
  }
  case PrimitiveType::Torus:
    lines.circle(p.origin, u, v, p.radius + p.minor_radius);
    lines.circle(p.origin, u, v, std::max(p.radius - p.minor_radius, 0.0));
    lines.circle(p.origin + p.minor_radius * d, u, v, p.radius);
    for (int i = 0; i < 12; ++i) {
      const Eigen::Vector3d dir = Lines::around(i, 12, u, v);
      lines.circle(p.origin + p.radius * dir, dir, d, p.minor_radius);
    }
    break;
  }

  Eigen::MatrixX3d out(Eigen::Index(lines.ends.size()), 3);
  for (std::size_t i = 0; i < lines.ends.size(); ++i)
    out.row(Eigen::Index(i)) = lines.ends[i].transpose();
  return out;
}

} // namespace primitive_edit
