// meridian_section.h: a plane and a cylinder or cone turning about its normal, seen in their meridian half-plane,
// where their edge is the corner of two lines and its fillet or chamfer is the one of two planes (edge_blend.h).
//
// Input:  an axis (a point and a direction) and a point towards which angles about it are measured from (a band's
//         samples' mean: its middle); points to map; a plane, a cylinder or a cone; a blend of the mapped space
//         to turn back.
// Output: meridian_frame: the axis, two unit directions square to it and the radius at which an angle reads as
//         an arc; std::nullopt when a number is not finite, the direction is zero or the point lies on the axis.
//         to_meridian(frame, p): (r, h, arc): r the distance of p from the axis, h its height along it, arc its
//         angle about the axis from the frame's first direction (in (-pi, pi]) times that radius; from_meridian
//         the inverse (for r >= 0). meridian_extent: the diagonal of the (r, h) box of the points of positive
//         weight (empty weights: all), the chord over which a profile about the axis is seen.
//         meridian_of_turned(frame, turned): a cylinder or cone on the frame's axis (its origin and axis the
//         frame's) as a plane of the mapped space whose normal has no arc part: r = R, or the cone's generator
//         line; std::nullopt for another type or an invalid one.
//         meridian_of_plane(frame, plane, near): the plane as the line h = const, at the height of near's foot on
//         the plane, for a plane near square to the axis; std::nullopt when it is no valid plane, `near` is not
//         finite or its normal is nearer than kMinBlendAngleDeg to square to the axis (a plane along the axis
//         has no such line).
//         revolve(frame, blend): a blend of the mapped space (a cylinder along arc: a fillet's circle; a plane: a
//         chamfer's line) as the surface it sweeps about the axis: a torus; a cone, or the cylinder or plane that
//         a line parallel or square to the axis sweeps. std::nullopt when the result is not valid (a circle
//         reaching the axis, a line through the axis square to it).
// Method: a surface of revolution is a curve of the meridian half-plane, and a point's distance to it is its
//         (r, h) distance to that curve (the torus's tube circle, the cone's generator line): in the mapped space
//         the two surfaces are planes along arc, and edge_blend.h's section, distances and sector hold as they
//         are. The arc keeps where along the edge a point lies, so that a window along the edge
//         (edge_blend_window.h) is an arc of the ring; it plays no part in a distance. A plane tilted from square
//         by a small angle is taken level at the blend (near), where its height matters.
// Cost:   O(1) per call.
#ifndef PRIMITIVE_EDIT_MERIDIAN_SECTION_H
#define PRIMITIVE_EDIT_MERIDIAN_SECTION_H

#include "common/base/primitive.h"

#include <Eigen/Core>

#include <optional>

namespace primitive_edit {

struct MeridianFrame
{
  Eigen::Vector3d origin, axis, first, second;
  double arc_radius = 1;
};

std::optional<MeridianFrame> meridian_frame(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                                            const Eigen::Vector3d& towards);

Eigen::Vector3d to_meridian(const MeridianFrame& frame, const Eigen::Vector3d& p);
Eigen::Vector3d from_meridian(const MeridianFrame& frame, const Eigen::Vector3d& q);

double meridian_extent(const MeridianFrame& frame, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights);

std::optional<Primitive> meridian_of_turned(const MeridianFrame& frame, const Primitive& turned);

std::optional<Primitive> meridian_of_plane(const MeridianFrame& frame, const Primitive& plane,
                                           const Eigen::Vector3d& near);

std::optional<Primitive> revolve(const MeridianFrame& frame, const Primitive& blend);

} // namespace primitive_edit

#endif
