#include "common/segment/fit_region_primitive.h"

namespace primitive_edit {

std::optional<Primitive> fit_region_primitive(const GrowingFaces& g, const std::vector<int>& faces,
                                              const Primitive* start, double tol, double angle, double share,
                                              int threads)
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
    const FitResult r =
        reduce_degenerate_cone(refine_primitive(*start, points, weights, fast), points, weights, tol, fast);
    if (accept(r))
      return r.primitive;
    return std::nullopt;
  }
  const FitResult plane = fit_plane(points, normals, weights);
  if (accept(plane))
    return plane.primitive;
  AutoFitOptions options;
  options.tolerance = 0.5 * tol;
  options.threads = threads;
  const AutoFitResult best = fit_primitive_auto(points, normals, weights, options);
  if (best.status.ok() && accept(best.best))
    return best.best.primitive;
  return std::nullopt;
}

} // namespace primitive_edit
