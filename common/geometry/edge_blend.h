// edge_blend.h: the fillet or chamfer of the edge of two planes, given its setback.
//
// Input:  two planes at an angle (normals at least kMinBlendAngleDeg from parallel), for each a point of the
//         half of it that the part keeps (the other side of the edge is cut away by the other plane), a point
//         near the edge (where along it), and for a blend its form and setback s > 0 (from the edge to each
//         tangent line, along the planes).
// Output: planes_line: the planes' common line (a point near a given one and its direction).
//         EdgeSection: a point of the planes' common line and its direction, the ray along each plane away
//         from the line (into the half kept), the rays' unit bisector and half the angle between them; the
//         blend's surface: for a fillet the cylinder tangent to both planes along the tangent lines (axis along
//         the line through bisector * s / cos(half angle), radius s * tan(half angle)), for a chamfer the plane
//         through both tangent lines (normal along the bisector); a point's distance to it; whether a point lies
//         in the blend's sector (nearer the line than both tangent lines, along the planes).
// Method: everything is measured in the cross-section, the line's direction removed: the blend is a circle or a
//         segment joining two rays. Given the planes, the setback is the blend's only parameter.
// Cost:   O(1) per call.
#ifndef PRIMITIVE_EDIT_EDGE_BLEND_H
#define PRIMITIVE_EDIT_EDGE_BLEND_H

#include "common/base/primitive.h"

#include <Eigen/Core>

#include <optional>

namespace primitive_edit {

constexpr double kMinBlendAngleDeg = 20.0; // planes nearer parallel (or anti-parallel) than this meet in no edge

enum class BlendForm { Fillet, Chamfer };

struct EdgeSection
{
  Eigen::Vector3d origin, direction, ray_a, ray_b, bisector;
  double half_angle = 0;
};

// The line two planes meet in: its point nearest `near` and its direction (a.axis x b.axis, normalised).
// std::nullopt when a plane is not a valid plane, the planes are too near parallel or `near` is not finite.
struct PlanesLine
{
  Eigen::Vector3d origin, direction;
};
std::optional<PlanesLine> planes_line(const Primitive& a, const Primitive& b, const Eigen::Vector3d& near);

// std::nullopt when planes_line has no line, a point is not finite or a `kept` point lies on the line.
std::optional<EdgeSection> edge_section(const Primitive& a, const Primitive& b, const Eigen::Vector3d& kept_a,
                                        const Eigen::Vector3d& kept_b, const Eigen::Vector3d& near);

// p in the section: from the section's origin, its component along the line removed.
Eigen::Vector3d in_section(const EdgeSection& section, const Eigen::Vector3d& p);

// How far p lies from the line along the plane of `ray` (negative: on the side cut away).
double distance_along(const EdgeSection& section, const Eigen::Vector3d& ray, const Eigen::Vector3d& p);

Primitive edge_blend_primitive(const EdgeSection& section, BlendForm form, double setback);

double edge_blend_distance(const EdgeSection& section, BlendForm form, double setback, const Eigen::Vector3d& p);

bool in_edge_blend_sector(const EdgeSection& section, double setback, const Eigen::Vector3d& p);

} // namespace primitive_edit

#endif
