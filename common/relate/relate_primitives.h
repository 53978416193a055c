// relate_primitives.h: the relations a part's fitted primitives share, and the primitives refitted together
// under them (issue: per-segment fits of a rough scan tilt, shift and resize each feature on its own).
//
// Input:  per segment its fitted primitive (std::nullopt: free-form, left out) and its samples
//         (gather_segment_samples.h: points and weights), the segments' contacts (segment_contacts.h), the
//         scan's noise (RMS; 0 or not finite: unknown), which segments are held fixed (empty: none),
//         RelationOptions, and the threads of the refits (refit_with_relations.h; the result is the same for any).
// Output: RelatedPrimitives: the relations kept, each segment's primitive after the joint refit (the input
//         where the segment is in no relation), the relations the check after the refit dropped, and a
//         status (failed, with the primitives untouched, only for bad options or, in a segment with a
//         primitive, non-finite samples or weights, negative weights or weights not one per point).
//         Nothing is invented: a relation is kept only when making it hold raises no segment's fit cost
//         (sum of squared distances) by more than options.max_cost_increase of it, first predicted
//         (detect_*_relations.h), then checked on the refit (at most twice that share: several relations add
//         up); a segment that fails the check loses its positional relations, then its directional ones, and
//         the refit is run again.
// Method: 1. directions: parallel classes and the part's frame (detect_direction_relations.h), refit
//            (refit_with_relations.h); 2. positions: coaxial, concentric, coplanar, equal radii, tangent
//            fillets (detect_position_relations.h) among the refitted primitives, refit with all relations;
//            3. the check. Every segment is represented by at most kRelateSamples of its points (evenly
//            strided, weights scaled to keep its total), weighted by its own fit's robust (Tukey) weights, so
//            that outliers at its border do not pull the joint fit either, and divided by its own fit's
//            mean squared residual, so that the joint fit trusts each segment as far as its noise allows.
// Cost:   O(N) to take the samples, then the detections and up to 6 refits on at most kRelateSamples points a
//         segment.
#ifndef PRIMITIVE_EDIT_RELATE_PRIMITIVES_H
#define PRIMITIVE_EDIT_RELATE_PRIMITIVES_H

#include "common/base/constants.h"
#include "common/base/known_scale.h"
#include "common/base/status.h"
#include "common/fit/check_fit_input.h"
#include "common/fit/fit_residuals.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/mesh/segment_contacts.h"
#include "common/relate/detect_direction_relations.h"
#include "common/relate/detect_position_relations.h"
#include "common/relate/fit_information.h"
#include "common/relate/refit_with_relations.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace primitive_edit {

struct RelationOptions
{
  double angle_deg = 10;           // directions within this of parallel, perpendicular or 45 degrees are candidates
  double distance = 0;             // positions within this are candidates; <= 0: 3 x the noise (1% of the part without)
  // The share by which a relation may raise a segment's fit cost (sum of squared distances). 1: the cost may
  // double (RMS x 1.41): on a rough scan the per-segment fits follow the roughness's waves, and holding them
  // by relations gains 1.6 points on the bundled scan over 0.1 (bench_segment_scan --relation-cost), while
  // a deliberate tilt or offset of a feature costs many times its noise and stays.
  double max_cost_increase = 1.0;
};

// The check after the joint refit: a segment's cost may reach this factor of its own fit's, twice the share a
// relation may ask at detection (several relations add up). The edit tool holds a picked face to it too.
inline double checked_cost_factor(double max_cost_increase) { return 1 + 2 * max_cost_increase; }

struct RelatedPrimitives
{
  Status status;
  std::vector<Relation> relations;  // kept, after the refit
  std::vector<std::optional<Primitive>> primitives;
  int dropped = 0;       // relations found but dropped by the check after the refit
  double distance = 0;   // the distance tolerance used
  double length = 0;     // the part's size, which turns a relation's angle residuals into distances
};

constexpr Eigen::Index kRelateSamples = 3000;

namespace relate_detail {

// At most `count` evenly strided samples with weights scaled to keep the total, times the robust weights of
// the segment's own fit at p.
RelatedSegment related_segment(const Primitive& p, const SegmentSamples& s, Eigen::Index count);

// The segment whose cost after the refit most exceeds checked_cost_factor of its own fit's, -1: none.
int worst_segment(const RelationRefit& refit, const std::vector<FitInformation>& own,
                  const std::vector<const Primitive*>& related, double max_cost_increase, double length);

// Drops segment `worst`'s positional relations, or its directional ones when it has no positional one left
// (worst < 0: all positional relations, then all); returns how many were dropped.
int drop_relations_of(int worst, std::vector<Relation>& kept, std::vector<char>& is_position);

} // namespace relate_detail

RelatedPrimitives relate_primitives(const std::vector<std::optional<Primitive>>& fitted,
                                    const std::vector<SegmentSamples>& samples,
                                    const std::vector<SegmentContact>& contacts, double noise,
                                    const RelationOptions& options, const std::vector<char>& fixed = {},
                                    int threads = 1);

} // namespace primitive_edit

#endif
