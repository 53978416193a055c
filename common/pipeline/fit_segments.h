// fit_segments.h: fit_segment on every segment of a mesh, on several threads.
//
// Input:  the segments' samples (gather_segment_samples.h), optionally a type per segment (std::nullopt or a
//         missing entry: the automatic type), the options of fit_segment, the number of threads (<= 0:
//         every CPU, resolve_thread_count in parallel_for.h), and an optional Progress (progress.h), called on the
//         calling thread only (so a GUI callback is safe) after each segment that thread fitted, with the share of
//         segments done; it may repeat a percentage. Fitting is not cancelled.
// Output: one FitResult per segment, in segment order; a failed status (free-form, too few points, ...) says
//         why. The results do not depend on the thread count: each segment is fitted by the same
//         deterministic code, whichever thread takes it.
// Method: the segments are handed out one at a time, largest first (for_each_largest_first, parallel_for.h),
//         so that a large segment does not start last and keep one thread busy while the others are idle.
// Cost:   the sum of the segments' fit costs divided by the threads used, plus O(K log K) for the order.
#ifndef PRIMITIVE_EDIT_FIT_SEGMENTS_H
#define PRIMITIVE_EDIT_FIT_SEGMENTS_H

#include "common/base/parallel_for.h"
#include "common/base/progress.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/pipeline/fit_segment.h"

#include <algorithm>
#include <atomic>
#include <optional>
#include <vector>

namespace primitive_edit {

std::vector<FitResult> fit_segments(const std::vector<SegmentSamples>& segments,
                                    const std::vector<std::optional<PrimitiveType>>& types = {},
                                    const AutoFitOptions& options = {}, int threads = 0,
                                    const Progress& progress = {});

} // namespace primitive_edit

#endif
