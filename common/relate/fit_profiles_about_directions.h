// fit_profiles_about_directions.h: curved segments whose axis follows none of the part's directions get the plane,
// cylinder, cone or torus about one of them that they are.
//
// Input:  part_directions: per segment its primitive (std::nullopt: free-form) and area, and the relations' angle
//         (degrees). fit_profiles_about_directions: per segment its primitive after the relations' refit and its
//         samples (gather_segment_samples.h), the scan's roughness, the fit tolerance (0: automatic, as
//         fit_primitive_auto.h takes it), the part's directions, the relations' angle, the types asked per segment
//         (may be empty; a segment asked a type keeps it) and the threads (parallel_for.h; the result is the same
//         for any).
// Output: part_directions: the normals of the part's planes, planes parallel within the angle as one class led by
//         its largest, each class holding at least kPartDirectionShare of the area of the segments with a primitive
//         (a fillet band fitted flat or a corner's round is the direction of no face of the part); none for an angle
//         outside [0, 90). fit_profiles_about_directions: one SegmentProfile per segment given a new primitive: the
//         segment, the plane whose normal its axis (a plane: its normal) follows (axis_segment), the primitive and its
//         RMS; none for an angle outside [0, 90). The caller replaces the segments' primitives.
// Method: a short band of a hole, a countersink or a corner fitted alone is at the noise floor of every type, and on a
//         rough scan a rich type bends to the waves and wins (fit_primitive_auto.h): on the bundled CT scan's true
//         segments the 2.75 mm hole through the plate's foot came out a torus whose axis lay across the hole's, and
//         its 45-degree countersink a torus tilted 32 degrees. A part's holes and corners turn about its own
//         directions, and with the direction given a type has 2 parameters fewer (fit_profile_about_direction.h).
//         So each cylinder, cone or torus segment whose axis lies beyond the angle from every direction is fitted
//         about each as a plane, a cylinder, a cone and a ring torus (a spindle one, its tube through its axis, is
//         a short band's noise floor, not a round), and takes the best scoring one (type_score with
//         direction_degrees_of_freedom), as fit_profiles_about_axes.h does, when
//         - its RMS is within the tolerance and at most kProfileRmsRatio times that of the segment's own
//           primitive, both capped_rms.h over at most kProfilePoints samples (the axis's position fitted on
//           kDirectionPoints of them), and
//         - its score is below the own primitive's (type_score with all its parameters).
//         A feature tilted off every direction fits none of them by its noise, and keeps its own primitive. A
//         sphere has no axis to be off, and a segment whose axis follows a direction is the joint refit's.
// Cost:   part_directions O(P^2) for P planes. fit_profiles_about_directions per candidate segment and direction,
//         for each type, kDirectionPoints samples times the profile's iterations per evaluation
//         (fit_profile_about_direction.h), then O(kProfilePoints) to fit and score it; segments divided by the
//         threads.
#ifndef PRIMITIVE_EDIT_FIT_PROFILES_ABOUT_DIRECTIONS_H
#define PRIMITIVE_EDIT_FIT_PROFILES_ABOUT_DIRECTIONS_H

#include "common/base/primitive.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/relate/fit_profiles_about_axes.h"

#include <optional>
#include <vector>

namespace primitive_edit {

constexpr Eigen::Index kDirectionPoints = 400;  // samples a candidate's axis is placed on
constexpr double kPartDirectionShare = 0.05;     // of the area, the planes of a direction of the part hold

struct PartDirection
{
  int segment = -1;  // the largest plane of the class
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};

std::vector<PartDirection> part_directions(const std::vector<std::optional<Primitive>>& primitives,
                                           const std::vector<double>& area, double angle_deg);

std::vector<SegmentProfile> fit_profiles_about_directions(const std::vector<std::optional<Primitive>>& primitives,
                                                          const std::vector<SegmentSamples>& samples,
                                                          double roughness, double tolerance,
                                                          const std::vector<PartDirection>& directions,
                                                          double angle_deg,
                                                          const std::vector<std::optional<PrimitiveType>>& types = {},
                                                          int threads = 1);

} // namespace primitive_edit

#endif
