// fit_circle_2d.h: algebraic circle fit in the plane (Taubin's normalisation, as in Chernov's TaubinSVD).
//
// Input:  points N x 2, weights N (empty = all 1), N >= 3 with positive weight.
// Output: centre and radius of the circle minimising sum w (|p|^2 + b.p + c)^2 under Taubin's gradient
//         normalisation (nearly unbiased, unlike the plain Kasa fit); ok == false when the points
//         are (nearly) collinear: the circle would have an absurd radius.
// Cost:   O(N) plus a 3 x 3 eigen decomposition.
#ifndef PRIMITIVE_EDIT_FIT_CIRCLE_2D_H
#define PRIMITIVE_EDIT_FIT_CIRCLE_2D_H

#include <Eigen/Eigenvalues>

#include <cmath>

namespace primitive_edit {

struct Circle2d
{
  bool ok = false;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0;
};

Circle2d fit_circle_2d(const Eigen::MatrixX2d& points, const Eigen::VectorXd& weights);

} // namespace primitive_edit

#endif
