// constrained_step.h: the step of a linearised least-squares problem with exact linear constraints, over
// unknowns that come in independent blocks (one block per segment's primitive).
//
// Input:  per block b: its normal matrix H_b (k_b x k_b, positive semi-definite) and gradient g_b (the data
//         term is 1/2 d^T H d + g^T d), its first column in the unknown vector; the constraints' Jacobian C
//         (m x n) and values c (the step must satisfy C d = -c); a Levenberg-Marquardt damping lambda >= 0.
// Output: the step d (n), or an empty vector when a damped block cannot be factorised or the result is not
//         finite. Redundant constraints (rows of C that depend on others) are harmless: the multipliers come
//         from a pseudo-inverse; contradictory ones are met in the least-squares sense.
// Method: KKT system by the Schur complement of the block-diagonal A = H + lambda diag(H): S = C A^-1 C^T,
//         mu = S^+ (c - C A^-1 g), d = -A^-1 (g + C^T mu).
// Cost:   O(sum k_b^3 + m n k) for the blocks, O(m^2 n + m^3) for S and its eigen-decomposition.
#ifndef PRIMITIVE_EDIT_CONSTRAINED_STEP_H
#define PRIMITIVE_EDIT_CONSTRAINED_STEP_H

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <vector>

namespace primitive_edit {

struct StepBlock
{
  Eigen::MatrixXd H;
  Eigen::VectorXd g;
  int offset = 0;
};

Eigen::VectorXd constrained_step(const std::vector<StepBlock>& blocks, const Eigen::MatrixXd& C,
                                 const Eigen::VectorXd& c, double lambda);

} // namespace primitive_edit

#endif
