// fit_edge_blends.h: segments that round or bevel the edge of two plane segments, or of a plane segment and a
// cylinder or cone segment turning about its normal, get the fillet or chamfer tangent to both, when it explains
// them as a blend should.
//
// Input:  per segment its primitive after the relations' refit (std::nullopt: free-form) and its samples
//         (gather_segment_samples.h), the segments' contacts (segment_contacts.h), the scan's roughness and the
//         fit tolerance (0: automatic, as fit_primitive_auto.h takes it), the types asked per segment (may be
//         empty; a segment asked to be a cylinder can only be two planes' fillet, a plane only their chamfer, a
//         torus only a fillet about an axis, a cone only a chamfer about one, other types neither), the blends
//         given (may be empty) and the angle (degrees) within which a cylinder's or cone's axis turns about a
//         plane's normal (0: no blends about an axis).
// Output: one SegmentEdgeBlend per segment given a blend: the segment, the two segments it joins, the section, the
//         form, the setback, the blend's surface, its RMS and where it touches each of the two (about an axis:
//         the meridian frame too, in whose space the section and setback are). The caller replaces the segments'
//         primitives.
// Method: on a rough scan a fillet or chamfer narrower than a few times the roughness is at the noise floor of a
//         free fit: on the bundled CT scan's true segments the 1.5 mm fillets came out as planes at 45 degrees,
//         and their least-squares radius, even with the planes given, about half the true one (the scan's
//         profile there is flatter than the CAD's). Its borders are not: a blend meets each plane along a tangent
//         line, and the segment's border with that plane runs there (1.55 and 1.67 mm from the edge for a
//         1.5 mm fillet). So for each segment touching two plane segments whose planes meet at an angle
//         (edge_blend.h), the setback is the mean of its two borders' distances from the edge (the contacts'
//         means), which must agree within the tolerance or kEdgeBlendBorderShare of the setback. The form, fillet
//         or chamfer, is the one of the smaller RMS, sqrt(sum(w * min(d, tolerance)^2) / sum(w)) over all the
//         segment's samples (at most kEdgeBlendPoints of them, evenly strided, for this and all the scores below).
//         The blend is a candidate when
//         - at least kEdgeBlendSectorShare of the segment's weight lies between its tangent lines;
//         - its RMS is within the tolerance and at most kEdgeBlendRmsRatio times that of the segment's own
//           primitive, measured alike (the blend's single parameter must not buy a worse fit), and
//         - its score (type_score, one parameter) is below the own primitive's;
//         or, when no pair passes those, when the segment's samples and its planes' about their edge (within
//         kBlendReachTolerances tolerances of it, along the segment's extent) are likelier under the blend than
//         under the sharp edge by kMinBlendGain or more, with the planes' own scatter beyond
//         kBlendSetbackTolerances tolerances (edge_blend_window.h, edge_blend_likelihood.h): the test the
//         segmentation's carve makes, for a segment between planes that was not carved, or whose record a save
//         has lost. Waves of a scan's roughness wider than a narrow blend tilt its own fit across it (the
//         bracket's 0.8 mm chamfer 33 on its true segment: its own plane 45 degrees off), so no RMS takes the
//         blend, while the edge's faces still show it.
//         About an axis (the boss's foot, the countersink of a hole, the rounded top of a boss: a torus or cone band
//         between a plane and a cylinder or cone whose axis is within the angle of the plane's normal), the same
//         tests run in the meridian half-plane of the cylinder or cone (meridian_section.h), where both are lines
//         and the blend's circle or line turns into a torus or cone; a border there is the mean of its points'
//         radii and heights (its own mean lies on the axis). On the bundled scan's true segments the boss's foot
//         (a torus of tube radius 2) fitted alone came out a sphere or a torus 41 degrees off the axis.
//         Of several pairs, the best score (else the largest gain) is the segment's candidate. A face
//         between two planes is either their blend or a plane with blends on both sides (a 3 mm wall between a
//         fillet and a chamfer scores as a large fillet of them too): the candidates are taken narrowest first,
//         and a segment that already joins a blend, or whose neighbours are blends, is skipped.
//         Blends given (the segmentation's, segment_blends_attribute.h) come first and need no test of their fit:
//         the segmentation found them against the sharp edge by the scan's own scatter, which a blend's RMS
//         cannot show when the blend stands off its edge by less than the roughness. A given blend is taken when
//         its segment still touches both planes, they are still planes, its borders lie on their planes' kept
//         halves and kGivenEdgeBlendSectorShare of it between its tangent lines (the relations may have moved the
//         planes since it was carved between them; its borders need not agree); its planes are then no
//         candidates (a wall between a given blend and another plane is not their blend).
// Cost:   O(contacts) to list each segment's planes, cylinders and cones, then per segment O(kEdgeBlendPoints)
//         for its own RMS and per pair of its neighbours whose borders agree O(kEdgeBlendPoints + kContactPoints)
//         for each form; for the likelihood, O(samples of the segment and its two neighbours) to take the window
//         and O(kBlendPoints) per cost.
#ifndef PRIMITIVE_EDIT_FIT_EDGE_BLENDS_H
#define PRIMITIVE_EDIT_FIT_EDGE_BLENDS_H

#include "common/base/primitive.h"
#include "common/geometry/edge_blend.h"
#include "common/geometry/meridian_section.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/mesh/segment_blends_attribute.h"
#include "common/mesh/segment_contacts.h"

#include <optional>
#include <vector>

namespace primitive_edit {

constexpr Eigen::Index kEdgeBlendPoints = 2000; // samples of a segment its blends and own primitive are scored on
constexpr double kEdgeBlendSectorShare = 0.7;
constexpr double kEdgeBlendBorderShare = 0.5;
constexpr double kEdgeBlendRmsRatio = 1.25;
// A given blend's sector share: the planes were refitted (relations) since its faces were carved between them.
constexpr double kGivenEdgeBlendSectorShare = 0.5;

struct SegmentEdgeBlend
{
  int segment = -1;
  int plane_a = -1, plane_b = -1;  // the segments it joins: plane_a a plane, plane_b a plane or, about an axis,
                                   // the cylinder or cone
  EdgeSection section;
  BlendForm form = BlendForm::Fillet;
  double setback = 0, rms = 0;
  Primitive primitive;
  Eigen::Vector3d contact_a = Eigen::Vector3d::Zero(), contact_b = Eigen::Vector3d::Zero();  // on the tangent lines
  std::optional<MeridianFrame> meridian = std::nullopt;  // about an axis: section and setback are in its space
};

std::vector<SegmentEdgeBlend> fit_edge_blends(const std::vector<std::optional<Primitive>>& primitives,
                                              const std::vector<SegmentSamples>& samples,
                                              const std::vector<SegmentContact>& contacts, double roughness,
                                              double tolerance,
                                              const std::vector<std::optional<PrimitiveType>>& types = {},
                                              const std::vector<SegmentBlendRecord>& given = {},
                                              double axis_angle_deg = 0);

} // namespace primitive_edit

#endif
