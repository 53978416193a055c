// detect_position_relations.h: coaxial and concentric features, coplanar faces, equal radii and fillets
// tangent to the faces they round, among fitted primitives.
//
// Input:  per segment its primitive (nullptr: none) and FitInformation (fit_information.h), the segments'
//         contacts (segment_contacts.h: only touching segments can be tangent), the largest angle (radians)
//         and distance (mesh units) a pair may be off a relation, the largest share `max_cost_increase` by
//         which a relation may raise a segment's fit cost (to first order), and the part's size.
// Output: the relations found, at most one per pair of segments and kind, without cycles within a kind
//         (each kind's relations form a forest over the segments, so that no group is tied twice):
//           Coaxial      two axes (cylinder, cone, torus) within the angle and each origin within the
//                        distance of the other's axis (a cone's apex: the foot of the other's origin on its
//                        axis instead, axis_point_facing);
//           Concentric   sphere centres within the distance; a sphere's centre within it of a cylinder's or
//                        cone's axis, or of a torus's centre; two coaxial tori whose centres are within it;
//           Coplanar     two planes within the angle, each origin within the distance of the other plane;
//           EqualRadius  radii (sphere, cylinder, torus tube) within the distance of each other;
//           Tangent      a cylinder or torus (the fillet: of two cylinders, the thinner) and a touching
//                        segment whose surface is within the distance of the fillet's radius from its spine
//                        (axis, tube centre circle) at their border, with the directions such a contact needs
//                        (a cylinder along a plane or parallel to a cylinder or cone; a torus coaxial with a
//                        cylinder, cone or torus, or square to a plane).
//         Candidates are tried from the closest (deviation over the distance, or angle over the angle), and
//         kept when relation_cost_increase.h finds that holding them raises neither segment's fit cost by
//         more than max_cost_increase of it.
// Cost:   O(K^2) candidate pairs for K segments plus the contacts, one 2-segment test each.
#ifndef PRIMITIVE_EDIT_DETECT_POSITION_RELATIONS_H
#define PRIMITIVE_EDIT_DETECT_POSITION_RELATIONS_H

#include "common/base/find_root.h"
#include "common/mesh/segment_contacts.h"
#include "common/relate/relation_cost_increase.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

namespace primitive_edit {

namespace position_detail {

double axis_angle(const Primitive& a, const Primitive& b);

// Distance of x from the axis line of p.
double distance_to_axis(const Primitive& p, const Eigen::Vector3d& x);

// The point of p's axis at which its offset from other's axis is measured: p's origin (a cylinder's is the axis
// point nearest its points, a torus's its centre), except a cone's apex, which on a slender cone lies far
// beyond the band its points cover (the boss of the bundled bracket: 60 mm off), so that a tilt within the
// angle tolerance moved it millimetres off a coaxial bore's axis; there, the foot of other's origin.
Eigen::Vector3d axis_point_facing(const Primitive& p, const Primitive& other);

struct Candidate
{
  double deviation;  // in units of the tolerance: 0 = exact, 1 = at the limit
  Relation relation;
};

void add_candidate(std::vector<Candidate>& out, double deviation, RelationKind kind, int a, int b,
                   double sign = 1, const Eigen::Vector3d& contact = Eigen::Vector3d::Zero());

// The relations of position one pair of segments a < b may hold, whether or not they touch.
void add_pair_candidates(const Primitive& pa, const Primitive& pb, int a, int b, double max_angle,
                         double max_distance, std::vector<Candidate>& out);

// Tangency of a fillet f (a cylinder or torus) with a segment g it touches at contact_point.
void add_tangent_candidate(const Primitive& pf, const Primitive& pg, int f, int g,
                           const Eigen::Vector3d& contact_point, double max_angle, double max_distance,
                           std::vector<Candidate>& out);

// From the closest candidate on: kept unless its kind already joins the pair through others (one forest per
// kind, so that no group is tied twice; tangency excepted) or holding it raises a segment's fit cost by more
// than max_cost_increase of it.
std::vector<Relation> affordable_candidates(std::vector<Candidate> candidates,
                                            const std::vector<const Primitive*>& primitives,
                                            const std::vector<FitInformation>& info, double max_cost_increase,
                                            double length);

} // namespace position_detail

std::vector<Relation> detect_position_relations(const std::vector<const Primitive*>& primitives,
                                                const std::vector<FitInformation>& info,
                                                const std::vector<SegmentContact>& contacts, double max_angle,
                                                double max_distance, double max_cost_increase, double length);

} // namespace primitive_edit

#endif
