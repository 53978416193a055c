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

const char* relation_kind_name(RelationKind kind);

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
bool has_axis(const Primitive& p);
// The radius a relation of equal radii compares (sphere, cylinder; a torus's tube), or 0.
double relation_radius(const Primitive& p);

// The components of each kind (for a pair of primitive types where the kind applies).
int relation_components(const Relation& r, const Primitive& a, const Primitive& b);

// The basis orthogonal to a's direction that Parallel, Coaxial, Coplanar and Concentric measure in; fixed
// during one refit step so that the components are smooth functions of both primitives.
struct RelationFrame
{
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY();
};

RelationFrame relation_frame(const Primitive& a);

// The part of d (from a's origin) off a's axis.
inline Eigen::Vector3d off_axis(const Primitive& a, const Eigen::Vector3d& d) { return d - d.dot(a.axis) * a.axis; }

// The point of a fillet's spine (a cylinder's axis, a torus's tube centre circle) nearest to x.
Eigen::Vector3d fillet_spine_point(const Primitive& f, const Eigen::Vector3d& x);

// out must have relation_components(r, a, b) rows.
void relation_residual(const Relation& r, const Primitive& a, const Primitive& b, const RelationFrame& frame,
                       double length, double* out);

// The relation's number, as the user reads it: Parallel 0, Perpendicular 90, Angle its angle (degrees);
// EqualRadius the radius of a; Tangent the fillet's radius; Coaxial, Concentric, Coplanar the distance
// between the two (0 when enforced).
double relation_value(const Relation& r, const Primitive& a, const Primitive& b);

} // namespace primitive_edit

#endif
