// fit_plane.h: least-squares plane through points.
//
// Input:  points N x 3 (N >= 3), normals N x 3 or empty, weights N or empty (= all 1), options.
// Output: FitResult with a Plane: origin = weighted centroid (of the inliers) projected onto the plane,
//         axis = unit normal, oriented along the sum of the given normals when there are normals,
//         otherwise with its largest component positive. A failed status for bad input or collinear points.
// Method: the weighted PCA plane (smallest principal axis) is the exact orthogonal least-squares
//         plane; refine_best_start.h then only adds the robust reweighting (on a 2000-point
//         subsample first for large inputs, then on all points).
// Cost:   O(N) per reweighting round.
#ifndef PRIMITIVE_EDIT_FIT_PLANE_H
#define PRIMITIVE_EDIT_FIT_PLANE_H

#include "common/fit/check_fit_input.h"
#include "common/fit/minimum_points_for.h"
#include "common/fit/fit_subsample.h"
#include "common/fit/refine_best_start.h"
#include "common/geometry/weighted_pca.h"

namespace primitive_edit {

inline FitResult fit_plane(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                           const Eigen::VectorXd& weights, const FitOptions& options = {})
{
  FitResult out;
  out.status = check_fit_input(points, normals, weights, minimum_points_for(PrimitiveType::Plane));
  if (!out.status)
    return out;
  const WeightedPca pca = weighted_pca(points, weights);
  if (!pca.ok || !(pca.eigenvalues[1] > 1e-12 * pca.eigenvalues[2])) {
    out.status = Status::failure("points are collinear or coincident: no unique plane");
    return out;
  }
  Primitive start;
  start.type = PrimitiveType::Plane;
  start.origin = pca.centroid;
  start.axis = pca.axes.col(0).normalized();
  double orientation = 0;
  if (normals.rows()) {
    for (Eigen::Index i = 0; i < normals.rows(); ++i)
      orientation += (weights.size() ? weights[i] : 1.0) * normals.row(i).dot(start.axis);
  } else {
    Eigen::Index k = 0;
    start.axis.cwiseAbs().maxCoeff(&k);
    orientation = start.axis[k];
  }
  if (orientation < 0)
    start.axis = -start.axis;
  return refine_best_start({start}, points, weights, fit_subsample(points, normals, weights, 2000), options);
}

} // namespace primitive_edit

#endif
