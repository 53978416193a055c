#include "common/relate/relation.h"

namespace primitive_edit {

const char* relation_kind_name(RelationKind kind)
{
  switch (kind) {
  case RelationKind::Parallel: return "parallel";
  case RelationKind::Perpendicular: return "perpendicular";
  case RelationKind::Angle: return "angle";
  case RelationKind::Coaxial: return "coaxial";
  case RelationKind::Concentric: return "concentric";
  case RelationKind::Coplanar: return "coplanar";
  case RelationKind::EqualRadius: return "equal_radius";
  case RelationKind::Tangent: return "tangent";
  }
  return "unknown";
}

bool has_axis(const Primitive& p)
{
  return p.type == PrimitiveType::Cylinder || p.type == PrimitiveType::Cone || p.type == PrimitiveType::Torus;
}

double relation_radius(const Primitive& p)
{
  switch (p.type) {
  case PrimitiveType::Sphere:
  case PrimitiveType::Cylinder: return p.radius;
  case PrimitiveType::Torus: return p.minor_radius;
  default: return 0.0;
  }
}

int relation_components(const Relation& r, const Primitive& a, const Primitive& b)
{
  switch (r.kind) {
  case RelationKind::Parallel: return 2;
  case RelationKind::Perpendicular:
  case RelationKind::Angle:
  case RelationKind::EqualRadius:
  case RelationKind::Tangent: return 1;
  case RelationKind::Coaxial: return 4;
  case RelationKind::Coplanar: return 3;
  case RelationKind::Concentric:
    if (a.type == PrimitiveType::Torus && b.type == PrimitiveType::Torus)
      return 5;
    if (has_axis(a) && b.type == PrimitiveType::Sphere && a.type != PrimitiveType::Torus)
      return 2;
    return 3;
  }
  return 0;
}

RelationFrame relation_frame(const Primitive& a)
{
  RelationFrame f;
  f.e1 = any_orthogonal(a.axis);
  f.e2 = a.axis.cross(f.e1);
  return f;
}

Eigen::Vector3d fillet_spine_point(const Primitive& f, const Eigen::Vector3d& x)
{
  const Eigen::Vector3d v = x - f.origin;
  if (f.type == PrimitiveType::Torus) {
    double rho = 0;
    return f.origin + f.radius * radial_direction(v, f.axis, &rho);
  }
  return f.origin + v.dot(f.axis) * f.axis;
}

void relation_residual(const Relation& r, const Primitive& a, const Primitive& b, const RelationFrame& frame,
                       double length, double* out)
{
  const Eigen::Vector3d& da = a.axis;
  const Eigen::Vector3d db = r.sign * b.axis;
  const Eigen::Vector3d d = b.origin - a.origin;
  // b's origin off a's axis, measured from the axis a has now (not through the step's fixed frame, which
  // would turn a long d along the axis into an offset: a cone's apex lies far along it).
  const Eigen::Vector3d off = off_axis(a, d);
  auto parallel = [&](double* o) {
    o[0] = length * frame.e1.dot(db - da);
    o[1] = length * frame.e2.dot(db - da);
  };
  switch (r.kind) {
  case RelationKind::Parallel: parallel(out); return;
  case RelationKind::Perpendicular: out[0] = length * da.dot(b.axis); return;
  case RelationKind::Angle: out[0] = length * (da.dot(db) - std::cos(radians_from_degrees(r.angle_deg))); return;
  case RelationKind::Coaxial:
    parallel(out);
    out[2] = frame.e1.dot(off);
    out[3] = frame.e2.dot(off);
    return;
  case RelationKind::Coplanar:
    parallel(out);
    out[2] = da.dot(d);
    return;
  case RelationKind::EqualRadius: out[0] = relation_radius(a) - relation_radius(b); return;
  case RelationKind::Tangent: {
    const Eigen::Vector3d spine = fillet_spine_point(a, r.contact);
    out[0] = r.sign * project_onto_primitive(b, spine).signed_distance - relation_radius(a);
    return;
  }
  case RelationKind::Concentric:
    if (a.type == PrimitiveType::Torus && b.type == PrimitiveType::Torus) {
      parallel(out);
      out[2] = frame.e1.dot(off);
      out[3] = frame.e2.dot(off);
      out[4] = da.dot(d);
    } else if (has_axis(a) && b.type == PrimitiveType::Sphere && a.type != PrimitiveType::Torus) {
      out[0] = frame.e1.dot(off);
      out[1] = frame.e2.dot(off);
    } else {
      out[0] = d.x();
      out[1] = d.y();
      out[2] = d.z();
    }
    return;
  }
}

double relation_value(const Relation& r, const Primitive& a, const Primitive& b)
{
  switch (r.kind) {
  case RelationKind::Parallel: return 0.0;
  case RelationKind::Perpendicular: return 90.0;
  case RelationKind::Angle: return r.angle_deg;
  case RelationKind::EqualRadius:
  case RelationKind::Tangent: return relation_radius(a);
  case RelationKind::Coaxial: return off_axis(a, b.origin - a.origin).norm();
  case RelationKind::Coplanar: return std::abs(a.axis.dot(b.origin - a.origin));
  case RelationKind::Concentric: {
    const Eigen::Vector3d d = b.origin - a.origin;
    return (has_axis(a) && b.type == PrimitiveType::Sphere && a.type != PrimitiveType::Torus) ? off_axis(a, d).norm()
                                                                                               : d.norm();
  }
  }
  return 0.0;
}

} // namespace primitive_edit
