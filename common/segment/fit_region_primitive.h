// fit_region_primitive.h: a primitive for a set of faces, accepted only when the faces agree with it.
//
// Input:  GrowingFaces (growing_faces.h), the faces, an optional start primitive, the distance tolerance,
//         the normal angle (radians) and the share of the faces' area that must agree (FaceAgreement).
// Output: the primitive, or std::nullopt when none is accepted.
// Method: on at most kFitSampleCount evenly strided faces (centroid, smoothed normal, area): with a start,
//         the start refined (refine_primitive, 10 iterations); without, a plane first, then
//         fit_primitive_auto at half the tolerance. The faces' agreeing share decides.
// Cost:   O(kFitSampleCount) per iteration of the fits, plus O(faces) for the share.
#ifndef PRIMITIVE_EDIT_FIT_REGION_PRIMITIVE_H
#define PRIMITIVE_EDIT_FIT_REGION_PRIMITIVE_H

#include "common/fit/fit_plane.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/refine_primitive.h"
#include "common/segment/growing_faces.h"

#include <optional>
#include <vector>

namespace primitive_edit {

constexpr int kFitSampleCount = 600; // faces a region's fit uses at most

inline std::optional<Primitive> fit_region_primitive(const GrowingFaces& g, const std::vector<int>& faces,
                                                     const Primitive* start, double tol, double angle, double share)
{
  Eigen::MatrixX3d points, normals;
  Eigen::VectorXd weights;
  face_samples(g, faces, kFitSampleCount, points, normals, weights);
  if (points.rows() < 3)
    return std::nullopt;
  auto accept = [&](const FitResult& r) {
    return r.status.ok() && primitive_is_valid(r.primitive) &&
           agreeing_share_reaches(g, r.primitive, faces, tol, angle, share);
  };
  if (start) {
    FitOptions fast;
    fast.max_iterations = 10;
    const FitResult r = refine_primitive(*start, points, weights, fast);
    if (accept(r))
      return r.primitive;
    return std::nullopt;
  }
  const FitResult plane = fit_plane(points, normals, weights);
  if (accept(plane))
    return plane.primitive;
  AutoFitOptions options;
  options.tolerance = 0.5 * tol;
  const AutoFitResult best = fit_primitive_auto(points, normals, weights, options);
  if (best.status.ok() && accept(best.best))
    return best.best.primitive;
  return std::nullopt;
}

} // namespace primitive_edit

#endif
