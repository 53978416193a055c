#include "common/fit/fit_cylinder.h"

namespace primitive_edit {

namespace {

// Radius of the start on nearly flat points, in units of their spread (the standard deviation along their
// longest axis): over a chord of a few spreads the circle bulges about 1e-6 of a spread, flatter than any
// scan, and the refinement takes it from there.
constexpr double kFlatStartRadius = 1e6;

} // namespace

FitResult fit_cylinder(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                       const Eigen::VectorXd& weights, const FitOptions& options)
{
  FitResult out;
  out.status = check_fit_input(points, normals, weights, minimum_points_for(PrimitiveType::Cylinder));
  if (!out.status)
    return out;
  const FitSample s = fit_subsample(points, normals, weights, 2000);
  std::vector<Eigen::Vector3d> directions;
  Eigen::Vector3d a;
  if (axis_orthogonal_to_normals(fit_start_normals(s), s.weights, &a))
    directions.push_back(a);
  const WeightedPca pca = weighted_pca(s.points, s.weights);
  for (int k = 2; k >= 0 && pca.ok; --k)
    directions.push_back(pca.axes.col(k).normalized());
  std::vector<Primitive> starts;
  for (const Eigen::Vector3d& d : directions) {
    const AxisCircle c = fit_circle_around_axis(s.points, s.weights, d);
    Primitive p;
    p.type = PrimitiveType::Cylinder;
    p.axis = d;
    if (c.ok) {
      p.origin = c.centre;
      p.radius = c.radius;
      starts.push_back(p);
      continue;
    }
    // Seen along d the points are a line: a plane, or nearly one. The cylinder that fits them is the one of
    // huge radius lying on that plane (which the callers then find implausibly large), not one about another
    // direction (a flat top with a hole took the cylinder about its normal through the hole: RMS 2.1, against
    // 1e-7 for the huge one).
    if (!pca.ok)
      continue;
    const Eigen::Vector3d flat_normal = pca.axes.col(0) - pca.axes.col(0).dot(d) * d;
    const double spread = std::sqrt(std::max(0.0, pca.eigenvalues.maxCoeff()));
    if (!(flat_normal.norm() > 0.5) || !(spread > 0))
      continue;
    p.radius = kFlatStartRadius * spread;
    p.origin = pca.centroid + p.radius * flat_normal.normalized();
    starts.push_back(p);
  }
  out = refine_best_start(starts, points, weights, s, options);
  if (out.status.ok())
    out.primitive.axis = largest_component_positive(out.primitive.axis);
  return out;
}

} // namespace primitive_edit
