// quadric_direct_common.h: what the type-constrained direct quadric fits (fit_*_direct.h) share.
//
// Input:  points N x 3, weights N (empty = all 1); a type's constraint subspace G(w) (9 x K) of the
//         quadric's coefficients for an axis direction w.
// Output: QuadricMoments (quadric_moments): the points centred on their weighted centroid and scaled to
//         unit RMS distance, the weighted scatter M = R^T R of the monomials
//         l(q) = (x^2, y^2, z^2, xy, xz, yz, x, y, z) about their mean (the constant term is eliminated:
//         the best one for coefficients c is c0 = -c . mean(l)) and Taubin's normalisation N = the
//         weighted sum of the monomials' gradient products. For f = c . l + c0, c^T M c / c^T N c is
//         sum w f^2 / sum w |grad f|^2, the Taubin-normalised algebraic distance Andrews & Sequin
//         (CAD&A 11(1), 2014) constrain per type. pencil_minimum() solves the K x K generalised
//         eigenproblem (G^T M G) t = lambda (G^T N G) t for a fixed w; minimise_over_axis() finds the
//         w of least lambda; check_direct_input() and direct_fit_result() are the fits' common
//         refusal and reporting.
// Method: the cylinder and cone constraints (A = I - w w^T; A = w w^T - cos^2(angle) I, up to scale)
//         are linear in the coefficients once the axis w is fixed, so the constrained problem is a
//         minimisation of the pencil's smallest eigenvalue over the sphere of directions (a hemisphere:
//         w and -w are the same constraint). It is not convex, so: 400 directions evenly spread on the
//         hemisphere (Fibonacci lattice, ~7 degrees apart); the 3 best mutually more than 20 degrees
//         apart, and the axis of the unconstrained Taubin quadric (exact on exact data, and found where
//         a narrow basin hides between grid points), are polished, best kept. The polish is
//         coarse-to-fine: a compass search (8 directions, step halved from 3 degrees to 0.06 degrees,
//         at most 30 rounds) gets into the basin, then Newton steps on the reduced
//         cost with central-difference gradient and Hessian in the tangent plane give the last digits
//         (exact data: the cost is 0 at the true axis, quadratic around it). The cost is evaluated as
//         the smallest singular value of R G L^-T (R from a QR of the design matrix, L L^T = G^T N G),
//         squared: forming M = R^T R would put a 1e-16 round-off floor under the cost and leave the
//         axis ~sqrt(1e-16 / curvature), i.e. ~1e-7, off on exact partial patches.
// Cost:   O(N) for the moments (a QR of the N x 9 design matrix); after that every evaluation is a
//         9 x K SVD (K <= 5, ~4 us), independent of N: 1000-1500 evaluations per fit.
#ifndef PRIMITIVE_EDIT_QUADRIC_DIRECT_COMMON_H
#define PRIMITIVE_EDIT_QUADRIC_DIRECT_COMMON_H

#include "common/base/canonicalize_primitive.h"
#include "common/base/constants.h"
#include "common/fit/check_fit_input.h"
#include "common/fit/fit_residuals.h"
#include "common/fit/minimum_points_for.h"
#include "common/geometry/closest_point_on_primitive.h"
#include "common/geometry/weighted_pca.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace primitive_edit {

namespace quadric_direct {

using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;

struct QuadricMoments
{
  bool ok = false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double scale = 1;  // RMS distance to the centroid: local q = (p - centroid) / scale
  Vec9 mean = Vec9::Zero();
  Mat9 R = Mat9::Zero();  // triangular factor of the centred, weighted design matrix: M = R^T R
  Mat9 N = Mat9::Zero();
};

Vec9 monomials(const Eigen::Vector3d& q);

// Coefficients of q^T A q + b . q (A symmetric) in the monomial basis.
Vec9 coefficients(const Eigen::Matrix3d& A, const Eigen::Vector3d& b);

QuadricMoments quadric_moments(const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights);

template <int K>
struct PencilMinimum
{
  double cost = std::numeric_limits<double>::infinity();  // smallest eigenvalue: algebraic / gradient
  Eigen::Matrix<double, K, 1> theta = Eigen::Matrix<double, K, 1>::Zero();  // its eigenvector
};

template <int K>
PencilMinimum<K> pencil_minimum(const QuadricMoments& m, const Eigen::Matrix<double, 9, K>& G, bool want_theta)
{
  using MatK = Eigen::Matrix<double, K, K>;
  MatK Q = G.transpose() * m.N * G;
  // Keeps Q positive definite when a constraint direction has no gradient on the data.
  Q.diagonal().array() += 1e-12 * Q.trace();
  const Eigen::LLT<MatK> llt(Q);
  PencilMinimum<K> out;
  if (llt.info() != Eigen::Success)
    return out;
  // theta = L^-T phi turns min |R G theta|^2 / theta^T Q theta into the smallest singular value of
  // R G L^-T: squared only at the end, so not limited by round-off of squared sums.
  const Eigen::Matrix<double, 9, K> B = llt.matrixU().template solve<Eigen::OnTheRight>(m.R * G);
  const Eigen::JacobiSVD<Eigen::Matrix<double, 9, K>> svd(B, want_theta ? Eigen::ComputeFullV : 0);
  // Eigen leaves the singular values unset for non-finite input: read them only after success.
  if (svd.info() != Eigen::Success)
    return out;
  const double sigma = svd.singularValues()[K - 1];
  out.cost = sigma * sigma;
  if (want_theta)
    out.theta = llt.matrixU().solve(Eigen::Matrix<double, K, 1>(svd.matrixV().col(K - 1)));
  return out;
}

// Local minimum of cost(w) on the unit sphere from w (see the header comment: compass, then Newton).
template <class Cost>
Eigen::Vector3d polish_axis(Eigen::Vector3d w, double f, const Cost& cost)
{
  // The round cap bounds the walk along a long flat valley (short arcs); Newton takes it from there.
  int moves = 0;
  for (double h = radians_from_degrees(3.0); h > 1e-3 && moves < 30; ++moves) {
    const Eigen::Vector3d e1 = any_orthogonal(w), e2 = w.cross(e1);
    Eigen::Vector3d best = w;
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector3d c = (w + h * (std::cos(k * kPi / 4) * e1 + std::sin(k * kPi / 4) * e2)).normalized();
      const double fc = cost(c);
      if (fc < f)
        f = fc, best = c;
    }
    if (best == w)
      h *= 0.5;
    w = best;
  }
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Eigen::Vector3d e1 = any_orthogonal(w), e2 = w.cross(e1);
    auto at = [&](double s, double t) { return cost((w + s * e1 + t * e2).normalized()); };
    // Small enough that the cubic terms of the cost do not bias the gradient near the minimum; the
    // cost is accurate to ~1e-32 (see quadric_moments), so the differences are not round-off.
    const double d = 1e-6;
    const double fpp = at(d, d), fpm = at(d, -d), fmp = at(-d, d), fmm = at(-d, -d);
    const double fp0 = at(d, 0), fm0 = at(-d, 0), f0p = at(0, d), f0m = at(0, -d);
    const Eigen::Vector2d g((fp0 - fm0) / (2 * d), (f0p - f0m) / (2 * d));
    Eigen::Matrix2d H;
    H(0, 0) = (fp0 - 2 * f + fm0) / (d * d);
    H(1, 1) = (f0p - 2 * f + f0m) / (d * d);
    H(0, 1) = H(1, 0) = (fpp - fpm - fmp + fmm) / (4 * d * d);
    // Only a convex model gives a Newton step towards the minimum; otherwise the compass result stands.
    if (!(H.determinant() > 0 && H(0, 0) > 0))
      break;
    const Eigen::Vector2d step = -H.inverse() * g;
    bool accepted = false;
    for (double s = 1; s > 1e-6 && !accepted; s *= 0.5) {
      const double fs = at(s * step.x(), s * step.y());
      if (fs < f) {
        f = fs;
        w = (w + s * step.x() * e1 + s * step.y() * e2).normalized();
        accepted = true;
      }
    }
    if (!accepted || step.norm() < 1e-12)
      break;
  }
  return w;
}

// The axis of the unconstrained Taubin quadric: the eigenvector of its A whose eigenvalue is farthest
// from the other two (exact for exact cylinder and cone data, a good seed for nearly exact data).
Eigen::Vector3d unconstrained_axis(const QuadricMoments& m);

// The axis direction of least pencil cost for the constraint subspace basis(w) (9 x K).
template <int K, class Basis>
Eigen::Vector3d minimise_over_axis(const QuadricMoments& m, const Basis& basis)
{
  auto cost = [&](const Eigen::Vector3d& w) { return pencil_minimum<K>(m, basis(w), false).cost; };
  const int count = 400;
  const double golden = kPi * (3 - std::sqrt(5.0));
  std::vector<std::pair<double, Eigen::Vector3d>> grid;
  grid.reserve(count);
  for (int i = 0; i < count; ++i) {
    const double z = (i + 0.5) / count, r = std::sqrt(1 - z * z);
    const Eigen::Vector3d w(r * std::cos(golden * i), r * std::sin(golden * i), z);
    grid.emplace_back(cost(w), w);
  }
  std::sort(grid.begin(), grid.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  // A basin narrower than the grid spacing (short arcs of thin cones) can hide between grid points.
  std::vector<Eigen::Vector3d> seeds;
  const Eigen::Vector3d unconstrained = unconstrained_axis(m);
  if (unconstrained.allFinite())
    seeds.push_back(unconstrained);
  const double apart = std::cos(radians_from_degrees(20.0));
  for (const auto& entry : grid) {  // not a structured binding: C++17 lambdas cannot capture one (clang)
    const Eigen::Vector3d& w = entry.second;
    if (seeds.size() == 4 || !std::isfinite(entry.first))
      break;
    if (std::all_of(seeds.begin(), seeds.end(), [&](const Eigen::Vector3d& s) { return std::abs(s.dot(w)) < apart; }))
      seeds.push_back(w);
  }
  Eigen::Vector3d best = grid.front().second;
  double best_cost = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& seed : seeds) {
    const Eigen::Vector3d w = polish_axis(seed, cost(seed), cost);
    const double c = cost(w);
    if (c < best_cost)
      best_cost = c, best = w;
  }
  return best;
}

// Rejects what no direct fit of `type` can use: check_fit_input's cases, collinear points and, for the
// curved types, coplanar points (a circle in a plane is a cylinder of any height, a cone of any apex).
Status check_direct_input(PrimitiveType type, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights);

// check_direct_input, then the points' moments: the start of the cylinder and cone fits. `status` says why
// when either fails.
QuadricMoments checked_quadric_moments(PrimitiveType type, const Eigen::MatrixX3d& points,
                                       const Eigen::VectorXd& weights, Status& status);

double data_extent(const Eigen::MatrixX3d& points);

// The FitResult of a read-off primitive: canonical conventions, orthogonal residuals over all points.
FitResult direct_fit_result(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& weights);

} // namespace quadric_direct

} // namespace primitive_edit

#endif
