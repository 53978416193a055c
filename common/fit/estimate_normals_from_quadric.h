// estimate_normals_from_quadric.h: surface normals of points from a Taubin-normalised algebraic quadric.
//
// Input:  points N x 3 (N >= 9 with positive weight), weights N (empty = all 1).
// Output: unit normals N x 3 (the normalised gradient of the fitted quadric at each point; a zero row
//         where the gradient vanishes), or an empty matrix when the fit is degenerate.
// Method: the direct quadric fit Andrews & Sequin build on (CAD&A 11(1), 2014): minimise the algebraic
//         distance c^T M c subject to Taubin's normalisation c^T N c = 1, N = sum of the monomials'
//         gradient products, a 9 x 9 generalised eigenproblem after eliminating the constant term
//         (data centred and scaled for conditioning). On exact cylinder / cone / sphere data the quadric
//         is exact, so are its normals; for other data they are an approximation that only seeds the
//         axis estimates of the fits when the caller has no normals. The normals' global sign is arbitrary.
// Cost:   O(N) plus a 9 x 9 generalised eigen decomposition.
#ifndef PRIMITIVE_EDIT_ESTIMATE_NORMALS_FROM_QUADRIC_H
#define PRIMITIVE_EDIT_ESTIMATE_NORMALS_FROM_QUADRIC_H

#include <Eigen/Eigenvalues>

#include <cmath>

namespace primitive_edit {

Eigen::MatrixX3d estimate_normals_from_quadric(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights);

} // namespace primitive_edit

#endif
