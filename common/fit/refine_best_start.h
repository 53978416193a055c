// refine_best_start.h: refine several start primitives and keep the best, cheaply on large inputs.
//
// Input:  start primitives (invalid ones are skipped), the full points N x 3 and weights (empty = all 1),
//         a subsample of them (fit_subsample.h; may be the full set), options.
// Output: the FitResult of the best start: each start is refined briefly (refine_primitive.h, at most
//         10 Levenberg-Marquardt iterations, no reweighting) on at most 500 points of the sample and
//         scored by the median |distance| over all of them (robust: not fooled by a start that fits a
//         small part and rejects the rest) or, with options.robust off, by the RMS; the winner is
//         refined fully (with the robust rounds) on the sample, then on all points when the sample is
//         smaller. A failed status when no start could be refined.
// Cost:   O(S * 500 * 10) for S starts, plus O((n + N) * iterations) for the winner.
#ifndef PRIMITIVE_EDIT_REFINE_BEST_START_H
#define PRIMITIVE_EDIT_REFINE_BEST_START_H

#include "common/fit/fit_subsample.h"
#include "common/fit/refine_primitive.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace primitive_edit {

FitResult refine_best_start(const std::vector<Primitive>& starts, const Eigen::MatrixX3d& points,
                            const Eigen::VectorXd& weights, const FitSample& sample,
                            const FitOptions& options);

} // namespace primitive_edit

#endif
