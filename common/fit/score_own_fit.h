// score_own_fit.h: how well a segment's own primitive fits it, the mark a replacement surface must beat
// (a fillet or chamfer between two planes, a profile about a cylinder's axis).
//
// Input:  the segment's samples (gather_segment_samples.h), its primitive (std::nullopt: none), the most points
//         to score on, the scan's roughness and the fit tolerance (<= 0: automatic_fit_tolerance from the
//         roughness and the subsample's extent).
// Output: std::nullopt when the samples are unusable (check_fit_input) or weigh nothing, or the cap is not
//         positive and finite; else the evenly strided subsample (fit_subsample.h), its bounding-box diagonal,
//         the cap, the primitive's capped RMS on the subsample (capped_rms.h; the cap without a primitive) and
//         its type_score (fit_primitive_auto.h; infinity without a primitive): a candidate is scored alike.
// Cost:   O(N) to check and stride the samples, O(max_points) distances.
#ifndef PRIMITIVE_EDIT_SCORE_OWN_FIT_H
#define PRIMITIVE_EDIT_SCORE_OWN_FIT_H

#include "common/base/primitive.h"
#include "common/fit/fit_subsample.h"
#include "common/mesh/gather_segment_samples.h"

#include <optional>

namespace primitive_edit {

struct OwnFitScore
{
  FitSample sample;
  double diagonal = 0, cap = 0, rms = 0, score = 0;
};

std::optional<OwnFitScore> score_own_fit(const SegmentSamples& own, const std::optional<Primitive>& primitive,
                                         Eigen::Index max_points, double roughness, double tolerance);

} // namespace primitive_edit

#endif
