// fit_profiles_about_axes.h: segments that turn about the axis of a hole or boss get the surface of revolution
// about that axis that their profile is.
//
// Input:  per segment its primitive after the relations' refit (std::nullopt: free-form) and its samples
//         (gather_segment_samples.h), the scan's roughness, the fit tolerance (0: automatic, as
//         fit_primitive_auto.h takes it), the relations' angle (degrees) and distance (> 0) within which an axis
//         is shared, and the types asked per segment (may be empty; a segment asked a type keeps it).
// Output: one SegmentProfile per segment given a new primitive: the segment, the cylinder segment whose axis it
//         turns about, the primitive (a cone, sphere or torus on that axis) and its RMS. The caller replaces the
//         segments' primitives.
// Method: a narrow band of a surface of revolution fitted alone is at the noise floor of its type: on the
//         bundled CT scan's true segments the boss's fillet tori (tube radii 1 and 2 mm) came out as spheres,
//         whose 4 parameters beat a free torus's 7, with their centres 0.3-0.5 mm off the bore's axis. About an
//         axis the part already has, each type is a curve of the meridian half-plane with 2 or 3 parameters
//         (fit_profile_about_axis.h). So each sphere, cone or torus segment whose own axis (a sphere: its
//         centre) lies within the angle and distance of a cylinder segment's axis is fitted about that axis as
//         a cone, a sphere and a torus, and takes the best scoring one (type_score with the profile's
//         parameters) when
//         - its RMS is within the tolerance and at most kProfileRmsRatio times that of the segment's own
//           primitive, both capped_rms.h over at most kProfilePoints samples (the shared axis must not buy a
//           worse fit), and
//         - its score is below the own primitive's (type_score with all its parameters), and
//         - for a sphere, its meridian arc sags more than the tolerance over the band (sagitta.h over the band's
//           extent in radius and height), as a free fit's sphere must over its data (fit_primitive_auto.h): a
//           shallower arc is no evidence of a sphere on a rough scan, and the band is the cone of its chord. On the
//           bundled scan's true segments the boss's drafted cone (half-angle 4.8 degrees) came out a sphere of radius
//           8.7 about the bore's axis, its arc sagging 0.44 over the band for a tolerance of 0.96, and then no fillet
//           could be tangent to it (fit_edge_blends.h).
//         Of several axes, the best score wins. Not a cylinder: a free cylinder already lost to the segment's
//         own type, and with the axis given its one parameter takes any band about it (the 1M scan's automatic
//         boss segment, a cone between two fillets: 82.9% within 0.42 mm as a cylinder, 83.6% as a sphere
//         about the bore's axis). Cylinders are the axes; coaxial ones are the joint refit's (relate_primitives.h).
// Cost:   O(segments x cylinders) to pair them, then per pair O(kProfilePoints) for the band's extent and
//         O(kProfilePoints x kProfileIterations) for each type.
#ifndef PRIMITIVE_EDIT_FIT_PROFILES_ABOUT_AXES_H
#define PRIMITIVE_EDIT_FIT_PROFILES_ABOUT_AXES_H

#include "common/base/primitive.h"
#include "common/mesh/gather_segment_samples.h"

#include <optional>
#include <vector>

namespace primitive_edit {

constexpr Eigen::Index kProfilePoints = 2000;  // samples of a segment its profiles and own primitive are scored on
constexpr double kProfileRmsRatio = 1.25;

struct SegmentProfile
{
  int segment = -1, axis_segment = -1;
  double rms = 0;
  Primitive primitive;
};

std::vector<SegmentProfile> fit_profiles_about_axes(const std::vector<std::optional<Primitive>>& primitives,
                                                    const std::vector<SegmentSamples>& samples, double roughness,
                                                    double tolerance, double angle_deg, double distance,
                                                    const std::vector<std::optional<PrimitiveType>>& types = {});

} // namespace primitive_edit

#endif
