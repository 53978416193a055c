// relation.h: a geometric relation between the primitives of two segments, as a machined part has them
// (parallel and perpendicular faces, coaxial holes and bosses, equal radii, fillets tangent to the faces
// they round), and the constraint it puts on them.
//
// Input:  a Relation (kind, the two segments, the data fixed when it was found) and the two primitives.
// Output: relation_residual: the constraint's components, all 0 exactly when the relation holds; angles are
//         multiplied by `length` (a size of the part) so that every component is a length and a joint
//         refit (refit_with_relations.h) weighs them alike. relation_value: the number the user reads (the
//         angle in degrees, the common radius, the fillet radius, the distance between coaxial axes...).
// The kinds and their components (a's direction: a plane's normal or an axis; e1, e2 orthogonal to it,
// fixed per refit step by relation_frame):
//   Parallel       directions parallel: e1.(b' - a), e2.(b' - a), b' = b's direction with a's sign (2)
//   Perpendicular  a.b (1)
//   Angle          value degrees between the directions: sign * a.b - cos(value) (1)
//   Coaxial        two axes on one line (cylinder, cone, torus): Parallel's 2 and b's origin on a's axis (2)
//   Concentric     sphere centres equal (3); a sphere's centre on an axis (2); tori: Coaxial's 4 and the
//                  centres at one height (1); torus and sphere: centres equal (3)
//   Coplanar       Parallel's 2 and b's point on a's plane (1)
//   EqualRadius    radius(a) - radius(b): sphere or cylinder radius, a torus's tube radius (1)
//   Tangent        a fillet (cylinder or torus, segment a) tangent to b: its spine (axis, or tube centre
//                  circle) at a distance of its radius from b, on the side it was found on, at the point
//                  of the spine nearest to `contact` (a point of their common border) (1)
// Cost:   O(1) per relation.
#ifndef PRIMITIVE_EDIT_RELATION_H
#define PRIMITIVE_EDIT_RELATION_H

#include "common/base/constants.h"
#include "common/base/primitive.h"
#include "common/geometry/closest_point_on_primitive.h"

#include <Eigen/Core>

#include <cmath>

namespace primitive_edit {

enum class RelationKind { Parallel, Perpendicular, Angle, Coaxial, Concentric, Coplanar, EqualRadius, Tangent };
constexpr int kRelationKindCount = 8;

inline const char* relation_kind_name(RelationKind kind)
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

struct Relation
{
  RelationKind kind = RelationKind::Parallel;
  int a = -1, b = -1;  // segment ids; Tangent: a is the fillet
  double angle_deg = 0;  // Angle: the angle between the directions (0 < angle < 90)
  // Fixed when the relation is found: Parallel, Angle, Coaxial, Coplanar, Concentric of tori: the sign that
  // orients b's direction like a's (+1 or -1); Tangent: the side of b the fillet's spine lies on.
  double sign = 1;
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();  // Tangent: a point of the border of a and b
};

// A primitive's direction (plane normal or axis); spheres have none.
inline bool has_direction(const Primitive& p) { return p.type != PrimitiveType::Sphere; }
// An axis of revolution: cylinder, cone, torus.
inline bool has_axis(const Primitive& p)
{
  return p.type == PrimitiveType::Cylinder || p.type == PrimitiveType::Cone || p.type == PrimitiveType::Torus;
}
// The radius a relation of equal radii compares (sphere, cylinder; a torus's tube), or 0.
inline double relation_radius(const Primitive& p)
{
  switch (p.type) {
  case PrimitiveType::Sphere:
  case PrimitiveType::Cylinder: return p.radius;
  case PrimitiveType::Torus: return p.minor_radius;
  default: return 0.0;
  }
}

// The components of each kind (for a pair of primitive types where the kind applies).
inline int relation_components(const Relation& r, const Primitive& a, const Primitive& b)
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

// The basis orthogonal to a's direction that Parallel, Coaxial, Coplanar and Concentric measure in; fixed
// during one refit step so that the components are smooth functions of both primitives.
struct RelationFrame
{
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY();
};

inline RelationFrame relation_frame(const Primitive& a)
{
  RelationFrame f;
  f.e1 = any_orthogonal(a.axis);
  f.e2 = a.axis.cross(f.e1);
  return f;
}

// The part of d (from a's origin) off a's axis.
inline Eigen::Vector3d off_axis(const Primitive& a, const Eigen::Vector3d& d) { return d - d.dot(a.axis) * a.axis; }

// The point of a fillet's spine (a cylinder's axis, a torus's tube centre circle) nearest to x.
inline Eigen::Vector3d fillet_spine_point(const Primitive& f, const Eigen::Vector3d& x)
{
  const Eigen::Vector3d v = x - f.origin;
  if (f.type == PrimitiveType::Torus) {
    double rho = 0;
    return f.origin + f.radius * radial_direction(v, f.axis, &rho);
  }
  return f.origin + v.dot(f.axis) * f.axis;
}

// out must have relation_components(r, a, b) rows.
inline void relation_residual(const Relation& r, const Primitive& a, const Primitive& b, const RelationFrame& frame,
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

// The relation's number, as the user reads it: Parallel 0, Perpendicular 90, Angle its angle (degrees);
// EqualRadius the radius of a; Tangent the fillet's radius; Coaxial, Concentric, Coplanar the distance
// between the two (0 when enforced).
inline double relation_value(const Relation& r, const Primitive& a, const Primitive& b)
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

#endif
