// fit_primitive_auto.h: fit every primitive type and choose the one the data is.
//
// Input:  points N x 3, normals N x 3 or empty, weights N or empty (= all 1), options: tolerance
//         (max acceptable RMS in mesh units; <= 0: the larger of 1% of the bounding-box diagonal of the
//         points of positive weight and 3 x options.roughness, the data's noise RMS if known) and the
//         per-fit options.
// Output: AutoFitResult: candidates = the fit of each type, in PrimitiveType order; best = the chosen
//         one; a failed status when the input is bad or nothing fits within the tolerance (free-form; best
//         is then the best-scoring fit, for information).
// Choice: score = max(rms, 1e-6 * diagonal) * (1 + 0.5 * degrees of freedom): a richer type has to
//         lower the RMS by 11-17% per extra parameter (a torus 44% below a plane), so nested types
//         (plane in sphere, cylinder in cone and torus) resolve to the simpler one. The penalty is
//         that large because a scan's error is spatially correlated (roughness, waviness): a richer
//         surface bends to follow it and gains far more than on independent noise. On the bundled CT
//         scan's true segments, 0.1 per parameter chose the right type for 71% of the area, 0.5 for
//         78% (bench_segment_scan --labels). The floor makes exact data choose the simplest exact
//         type. Degenerate fits are not eligible: a sphere or cylinder that sags less than the
//         tolerance over the data (a plane), a cone whose radius changes by less than the tolerance
//         along the data (a cylinder, reduce_degenerate_cone.h), a torus whose major radius exceeds 100
//         diagonals (a cylinder). Candidates must have rms <= tolerance.
// Speed:  with more than kAutoFitScreenPoints (300) points the candidates are fitted on an evenly
//         strided subsample of that size, with at most 20 iterations per round (their rms /
//         max_residual / point_count refer to it): enough to rank the types, and 5-10 times cheaper
//         than screening on thousands of points. Only the chosen type is then refined on all points
//         (its candidate entry is replaced by that full fit). With options.threads > 1 the candidates are
//         fitted side by side, costliest first (on a noisy plane patch a cone or torus takes 20-25 times a
//         plane), each into its own entry, so the choice is the one a single thread makes.
// Cost:   O(5 * 300 * 20 * starts) for the screening (at best halved on 2 threads or more: the cone and the torus
//         are each about 40% of it) plus O(N * iterations) for the final refinement.
#ifndef PRIMITIVE_EDIT_FIT_PRIMITIVE_AUTO_H
#define PRIMITIVE_EDIT_FIT_PRIMITIVE_AUTO_H

#include "common/base/known_scale.h"
#include "common/fit/fit_primitive.h"
#include "common/fit/fit_subsample.h"
#include "common/fit/reduce_degenerate_cone.h"
#include "common/fit/refine_primitive.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace primitive_edit {

struct AutoFitOptions
{
  double tolerance = 0;  // max acceptable RMS in mesh units; <= 0: automatic (see roughness)
  double roughness = 0;  // the data's noise RMS (estimate_surface_roughness.h), or 0 if unknown (so is a value not
                         // finite): the automatic tolerance is max(1% of the bounding-box diagonal, 3 x roughness)
  FitOptions fit;
  int threads = 1;       // the candidate types are fitted on this many threads (<= 0: all); the result is the same
};

struct AutoFitResult
{
  Status status;                     // failure: free-form (nothing fits within tolerance) or bad input
  FitResult best;                    // best fit (also filled when free-form, for information)
  std::vector<FitResult> candidates; // all tried, in PrimitiveType order
};

// The type choice's score (lower is better) of a fit of `dof` parameters with this RMS over points whose bounding
// box has this diagonal; see Choice above.
constexpr double kTypePenaltyPerParameter = 0.5;
inline double type_score(double rms, int dof, double diagonal)
{
  return std::max(rms, 1e-6 * diagonal) * (1.0 + kTypePenaltyPerParameter * dof);
}

// The automatic tolerance: 1% of the points' bounding-box diagonal, or 3 x the roughness when larger.
inline double automatic_fit_tolerance(double diagonal, double roughness)
{
  return std::max(0.01 * diagonal, 3.0 * (is_known_scale(roughness) ? roughness : 0.0));
}

// Points the candidate types are screened on; see Speed above.
constexpr Eigen::Index kAutoFitScreenPoints = 300;

namespace fit_auto_detail {

// Every type's fit of the screening sample, in PrimitiveType order, on up to `threads` threads.
std::vector<FitResult> screen_candidates(const FitSample& s, const FitOptions& options, int threads);

} // namespace fit_auto_detail

AutoFitResult fit_primitive_auto(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                                 const Eigen::VectorXd& weights, const AutoFitOptions& options = {});

} // namespace primitive_edit

#endif
