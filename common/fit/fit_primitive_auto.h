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
//         tolerance over the data (a plane), a cone whose radius
//         changes by less than the tolerance along the data (a cylinder), a torus whose major radius
//         exceeds 100 diagonals (a cylinder). Candidates must have rms <= tolerance.
// Speed:  with more than kAutoFitScreenPoints (300) points the candidates are fitted on an evenly
//         strided subsample of that size, with at most 20 iterations per round (their rms /
//         max_residual / point_count refer to it): enough to rank the types, and 5-10 times cheaper
//         than screening on thousands of points. Only the chosen type is then refined on all points
//         (its candidate entry is replaced by that full fit).
// Cost:   O(5 * 300 * 20 * starts) for the screening plus O(N * iterations) for the final refinement.
#ifndef PRIMITIVE_EDIT_FIT_PRIMITIVE_AUTO_H
#define PRIMITIVE_EDIT_FIT_PRIMITIVE_AUTO_H

#include "common/base/known_scale.h"
#include "common/fit/fit_primitive.h"
#include "common/fit/fit_subsample.h"
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
};

struct AutoFitResult
{
  Status status;                     // failure: free-form (nothing fits within tolerance) or bad input
  FitResult best;                    // best fit (also filled when free-form, for information)
  std::vector<FitResult> candidates; // all tried, in PrimitiveType order
};

// Points the candidate types are screened on; see Speed above.
constexpr Eigen::Index kAutoFitScreenPoints = 300;

namespace fit_auto_detail {

// Extent of the points (w > 0) along the axis: the length over which a cone's taper is seen.
inline double axial_extent(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights, const Eigen::Vector3d& axis)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (!weights.size() || weights[i] > 0) {
      const double h = points.row(i).dot(axis);
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
  return hi > lo ? hi - lo : 0.0;
}

} // namespace fit_auto_detail

inline AutoFitResult fit_primitive_auto(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                                        const Eigen::VectorXd& weights, const AutoFitOptions& options = {})
{
  AutoFitResult out;
  out.status = check_fit_input(points, normals, weights, minimum_points_for(PrimitiveType::Plane));
  if (!out.status)
    return out;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (!weights.size() || weights[i] > 0) {
      lo = lo.cwiseMin(points.row(i).transpose());
      hi = hi.cwiseMax(points.row(i).transpose());
    }
  const double diagonal = (hi - lo).norm();
  if (!(diagonal > 0)) {
    out.status = Status::failure("all points coincide");
    return out;
  }
  // A rough scan's segments deviate from their primitive by its roughness whatever their size.
  const double roughness = is_known_scale(options.roughness) ? options.roughness : 0.0;
  const double tolerance = options.tolerance > 0 ? options.tolerance : std::max(0.01 * diagonal, 3.0 * roughness);
  const FitSample s = fit_subsample(points, normals, weights, kAutoFitScreenPoints);
  FitOptions screen_options = options.fit;
  screen_options.max_iterations = std::min(screen_options.max_iterations, 20);

  int chosen = -1;
  double chosen_score = std::numeric_limits<double>::infinity();
  int fallback = -1;
  double fallback_score = std::numeric_limits<double>::infinity();
  for (int t = 0; t < kPrimitiveTypeCount; ++t) {
    const PrimitiveType type = static_cast<PrimitiveType>(t);
    out.candidates.push_back(fit_primitive(type, s.points, s.normals, s.weights, screen_options));
    const FitResult& c = out.candidates.back();
    if (!c.status.ok())
      continue;
    const double score = std::max(c.rms, 1e-6 * diagonal) * (1.0 + 0.5 * primitive_degrees_of_freedom(type));
    const Primitive& p = c.primitive;
    bool eligible = c.rms <= tolerance;
    if (type == PrimitiveType::Sphere || type == PrimitiveType::Cylinder)
      eligible = eligible && p.radius - std::sqrt(std::max(0.0, p.radius * p.radius - 0.25 * diagonal * diagonal)) >
                                 tolerance;
    if (type == PrimitiveType::Cone)
      eligible = eligible && fit_auto_detail::axial_extent(s.points, s.weights, p.axis) * std::tan(p.half_angle) >
                                 tolerance;
    if (type == PrimitiveType::Torus)
      eligible = eligible && p.radius < 100 * diagonal;
    if (eligible && score < chosen_score) {
      chosen = t;
      chosen_score = score;
    }
    if (score < fallback_score) {
      fallback = t;
      fallback_score = score;
    }
  }
  if (chosen < 0) {
    out.status = Status::failure(fallback < 0 ? "no primitive type could be fitted"
                                 : "free-form: no primitive fits within the tolerance " + std::to_string(tolerance));
    if (fallback >= 0)
      out.best = out.candidates[static_cast<size_t>(fallback)];
    return out;
  }
  // The screen may have stopped early or seen a subsample: the winner gets the full refinement.
  FitResult& winner = out.candidates[static_cast<size_t>(chosen)];
  FitResult full = refine_primitive(winner.primitive, points, weights, options.fit, 2);
  if (full.status.ok())
    winner = full;
  out.best = winner;
  if (!(winner.rms <= tolerance))
    out.status = Status::failure("free-form: the chosen " + std::string(primitive_type_name(winner.primitive.type)) +
                                 " exceeds the tolerance on all points");
  return out;
}

} // namespace primitive_edit

#endif
