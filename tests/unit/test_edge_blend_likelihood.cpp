// The likelihood of points about the edge of two planes under a blend (common/geometry/edge_blend_likelihood.h): on
// the edge of a plate (top z = 5, side y = 0, along x), points drawn uniformly along a sharp, filleted or chamfered
// profile and moved by isotropic noise as large as a CT scan's roughness; the setback found is the true one, where
// least squares of the distances finds a blend at the sharp edge and a small one at the fillet.
#include "common/base/constants.h"
#include "common/geometry/edge_blend.h"
#include "common/geometry/edge_blend_likelihood.h"

#include "test_fit_data.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace primitive_edit;

EdgeSection plate_edge()
{
  const std::optional<EdgeSection> e = edge_section(test_fit::make_plane({0, 0, 5}, {0, 0, 1}),
                                                    test_fit::make_plane({0, 0, 0}, {0, -1, 0}), {20, 10, 5},
                                                    {20, 0, 2}, {20, 0, 5});
  EXPECT_TRUE(e.has_value());
  return *e;
}

// n points drawn by length along the profile (5 mm of each face from the edge, the blend between), x in [0, 40),
// moved by isotropic Gaussian noise of sigma in the section.
void profile_points(BlendForm form, double setback, double sigma, int n, unsigned seed, Eigen::MatrixX3d& points,
                    Eigen::VectorXd& weights)
{
  constexpr double reach = 5.0, pi = kPi;
  const double blend = form == BlendForm::Fillet ? 0.5 * pi * setback : std::sqrt(2.0) * setback;
  const double length = 2 * (reach - setback) + blend;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::normal_distribution<double> N(0.0, sigma);
  points.resize(n, 3);
  weights.setOnes(n);
  for (int i = 0; i < n; ++i) {
    double t = length * U(rng), y, z;
    if (t < reach - setback) { // the top, from y = reach to the tangent line
      y = reach - t, z = 5;
    } else if ((t -= reach - setback) < blend) {
      if (form == BlendForm::Fillet) {
        const double a = t / setback; // from the top's tangent line
        y = setback - setback * std::sin(a), z = 5 - setback + setback * std::cos(a);
      } else {
        y = setback * (1 - t / blend), z = 5 - setback * t / blend;
      }
    } else { // the side, from the tangent line down
      t -= blend;
      y = 0, z = 5 - setback - t;
    }
    points.row(i) << 40 * U(rng), y + N(rng), z + N(rng);
  }
}

TEST(EdgeBlendLikelihood, FindsTheSetbackWhereLeastSquaresDoesNot)
{
  const EdgeSection e = plate_edge();
  Eigen::MatrixX3d points;
  Eigen::VectorXd weights;
  for (unsigned seed : {1u, 2u}) {
    profile_points(BlendForm::Fillet, 1.5, 0.5, 3000, seed, points, weights);
    const std::optional<EdgeBlendEstimate> fillet = best_edge_blend(e, points, weights, 0.5, 4.0, 3.0);
    ASSERT_TRUE(fillet.has_value());
    EXPECT_GT(fillet->gain, 20.0);
    // A fillet, or the chamfer through nearly the same points (a 1.5 mm fillet's mid-arc is where a chamfer of
    // setback about 1 mm passes).
    if (fillet->form == BlendForm::Fillet)
      EXPECT_NEAR(fillet->setback, 1.5, 0.4) << "seed " << seed;
    else
      EXPECT_NEAR(fillet->setback, 1.0, 0.4) << "seed " << seed;

    profile_points(BlendForm::Fillet, 0.0, 0.5, 3000, seed, points, weights);
    const std::optional<EdgeBlendEstimate> sharp = best_edge_blend(e, points, weights, 0.5, 4.0, 3.0);
    ASSERT_TRUE(sharp.has_value());
    EXPECT_LT(sharp->gain, 10.0) << "seed " << seed;
    EXPECT_LE(sharp->setback, 0.5) << "seed " << seed;
  }
}

TEST(EdgeBlendLikelihood, ChamferOnLowNoise)
{
  const EdgeSection e = plate_edge();
  Eigen::MatrixX3d points;
  Eigen::VectorXd weights;
  profile_points(BlendForm::Chamfer, 1.2, 0.05, 2000, 3, points, weights);
  const std::optional<EdgeBlendEstimate> b = best_edge_blend(e, points, weights, 0.05, 4.0, 3.0);
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(b->form, BlendForm::Chamfer);
  EXPECT_NEAR(b->setback, 1.2, 0.11);
  EXPECT_GT(b->gain, 1000.0);
}

TEST(EdgeBlendLikelihood, BadInputIsRefused)
{
  const EdgeSection e = plate_edge();
  Eigen::MatrixX3d points(1, 3);
  points << 20, 0, 5;
  Eigen::VectorXd weights = Eigen::VectorXd::Ones(1);
  EXPECT_FALSE(best_edge_blend(e, points, weights, 0.0, 4.0, 3.0));
  EXPECT_FALSE(best_edge_blend(e, points, weights, std::nan(""), 4.0, 3.0));
  EXPECT_FALSE(best_edge_blend(e, points, weights, 0.5, 4.0, 4.0));
  EXPECT_FALSE(best_edge_blend(e, points, Eigen::VectorXd::Ones(2), 0.5, 4.0, 3.0));
  Eigen::MatrixX3d far(1, 3);
  far << 20, 30, 5;
  EXPECT_FALSE(best_edge_blend(e, far, weights, 0.5, 4.0, 3.0));
}

} // namespace
