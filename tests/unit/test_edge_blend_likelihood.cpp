// The likelihood of points about the edge of two planes under a blend (common/geometry/edge_blend_likelihood.h): on
// the edge of a plate (top z = 5, side y = 0, along x), points drawn uniformly along a sharp, filleted or chamfered
// profile and moved by isotropic noise as large as a CT scan's roughness; the setback found is the true one, where
// least squares of the distances finds a blend at the sharp edge and a small one at the fillet. And the window
// those points are gathered in (common/geometry/edge_blend_window.h): its spread is the planes' own scatter.
#include "common/base/constants.h"
#include "common/geometry/edge_blend.h"
#include "common/geometry/edge_blend_likelihood.h"
#include "common/geometry/edge_blend_window.h"

#include "test_fit_data.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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

// The cost of one point against the profile's density integrated by brute force: the legs from the tangent points to
// 3 sigma past the reach and the blend, each in steps of 1e-4, under the Gaussian of sigma in the section.
double brute_force_cost(const EdgeSection& e, const Eigen::Vector3d& p, double sigma, double reach, BlendForm form,
                        double s)
{
  const Eigen::Vector3d q = in_section(e, p);
  auto gauss = [&](const Eigen::Vector3d& x) {
    return std::exp(-(q - x).squaredNorm() / (2 * sigma * sigma)) / (2 * kPi * sigma * sigma);
  };
  constexpr double ds = 1e-4;
  const double far = reach + 3 * sigma;
  double density = 0;
  for (double t = s + 0.5 * ds; t < far; t += ds)
    density += (gauss(t * e.ray_a) + gauss(t * e.ray_b)) * ds;
  double blend = 0;
  if (form == BlendForm::Fillet) {
    const Eigen::Vector3d centre = e.bisector * (s / std::cos(e.half_angle));
    const double radius = s * std::tan(e.half_angle);
    const Eigen::Vector3d u = (s * e.ray_a - centre) / radius, w = (s * e.ray_b - centre) / radius;
    const Eigen::Vector3d v = (w - u * w.dot(u)).normalized();
    const double sweep = kPi - 2 * e.half_angle;
    blend = radius * sweep;
    for (double a = 0.5 * ds / radius; a < sweep; a += ds / radius)
      density += gauss(centre + radius * (std::cos(a) * u + std::sin(a) * v)) * ds;
  } else {
    blend = s * (e.ray_b - e.ray_a).norm();
    const Eigen::Vector3d along = (e.ray_b - e.ray_a).normalized();
    for (double t = 0.5 * ds; t < blend; t += ds)
      density += gauss(s * e.ray_a + t * along) * ds;
  }
  const double inside = 2 * (reach - s) + blend;
  return -std::log((1 - kBlendOutlierShare) * density / inside + kBlendOutlierShare / (4 * reach * reach));
}

TEST(EdgeBlendLikelihood, CostIsTheProfilesDensityIntegrated)
{
  const EdgeSection e = plate_edge();
  constexpr double sigma = 0.2, reach = 2.0;
  for (BlendForm form : {BlendForm::Fillet, BlendForm::Chamfer})
    for (double s : {0.0, 0.4, 1.2})
      for (const Eigen::Vector3d& p : {Eigen::Vector3d(20, 0.3, 4.9), Eigen::Vector3d(7, 1.5, 5.2),
                                      Eigen::Vector3d(-3, 0.1, 3.8), Eigen::Vector3d(20, 0.9, 4.6)}) {
        Eigen::MatrixX3d points(1, 3);
        points.row(0) = p.transpose();
        const double cost = edge_blend_cost(e, points, Eigen::VectorXd::Ones(1), sigma, reach, form, s);
        EXPECT_NEAR(cost, brute_force_cost(e, p, sigma, reach, form, s), 2e-3)
            << "form " << int(form) << " setback " << s << " point " << p.transpose();
      }
}

TEST(EdgeBlendLikelihood, SetbackOutsideTheReachCostsInfinity)
{
  const EdgeSection e = plate_edge();
  Eigen::MatrixX3d points(1, 3);
  points << 20, 0.3, 4.9;
  const Eigen::VectorXd weights = Eigen::VectorXd::Ones(1);
  for (double s : {2.0, 3.5, -0.1, std::nan("")})
    EXPECT_EQ(edge_blend_cost(e, points, weights, 0.2, 2.0, BlendForm::Fillet, s),
              std::numeric_limits<double>::infinity())
        << "setback " << s;
  EXPECT_TRUE(std::isfinite(edge_blend_cost(e, points, weights, 0.2, 2.0, BlendForm::Fillet, 1.9)));
}

// Tolerance 0.5: reach 2.5, largest setback 2. Only the top's points 2-2.5 from the edge give the spread; the
// blend's points, the top's nearer the edge and the side's beyond the reach do not.
TEST(EdgeBlendWindow, SpreadIsThePlanesScatterBeyondTheLargestSetback)
{
  const EdgeSection e = plate_edge();
  const Primitive top = test_fit::make_plane({0, 0, 5}, {0, 0, 1});
  const Primitive side = test_fit::make_plane({0, 0, 0}, {0, -1, 0});
  EdgeBlendWindow window(e, 0.5);
  EXPECT_DOUBLE_EQ(window.reach(), kBlendReachTolerances * 0.5);
  EXPECT_DOUBLE_EQ(window.max_setback(), kBlendSetbackTolerances * 0.5);
  window.add({20, 0.5, 4.0}, 1.0);                      // the blend's: anywhere, no scatter
  window.add_on_plane({20, 1.0, 6.0}, 1.0, e.ray_a, top); // within the largest setback
  window.add_on_plane({20, 2.2, 5.3}, 1.0, e.ray_a, top);
  window.add_on_plane({21, 2.3, 4.7}, 3.0, e.ray_a, top);
  window.add_on_plane({20, 0.9, 2.0}, 1.0, e.ray_b, side); // 3 down the side: beyond the reach
  const std::optional<EdgeBlendSample> s = window.sample();
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->spread, 0.3, 1e-12);
  ASSERT_EQ(s->points.rows(), 5);
  EXPECT_EQ(s->weights.sum(), 7.0);

  EdgeBlendWindow exact(e, 0.5);
  exact.add_on_plane({20, 2.2, 5.0}, 1.0, e.ray_a, top);
  ASSERT_TRUE(exact.sample().has_value());
  EXPECT_DOUBLE_EQ(exact.sample()->spread, 0.05); // a tenth of the tolerance
}

TEST(EdgeBlendWindow, StridesToTheLikelihoodsPointsAndNeedsAPlanesScatter)
{
  const EdgeSection e = plate_edge();
  const Primitive top = test_fit::make_plane({0, 0, 5}, {0, 0, 1});
  EdgeBlendWindow window(e, 0.5);
  for (int i = 0; i < 3 * kBlendPoints; ++i)
    window.add({0.01 * i, 0.5, 4.0}, 1.0);
  EXPECT_FALSE(window.sample()) << "no plane's point beyond the largest setback";
  window.add_on_plane({0, 2.2, 5.1}, 1.0, e.ray_a, top);
  const std::optional<EdgeBlendSample> s = window.sample();
  ASSERT_TRUE(s.has_value());
  ASSERT_EQ(s->points.rows(), kBlendPoints);
  EXPECT_EQ(s->points(0, 0), 0.0);
  EXPECT_NEAR(s->points(1, 0), 0.01 * 3, 1e-12); // every third point, in the order added

  EdgeBlendWindow none(e, 0.0);
  none.add_on_plane({0, 2.2, 5.1}, 1.0, e.ray_a, top);
  EXPECT_FALSE(none.sample());
}

} // namespace
