// Unit tests of refine_detail::normal_equations, which accumulates only the block of each type's own parameters:
// on points around every primitive type, its cost, J^T W J and J^T W r must equal bit for bit what residual()'s
// full 7-vector Jacobian and a 7 x 7 outer product give, the other entries zero. The refinement's results, and so
// the segmentation's, then do not depend on how the sums are laid out.
#include "common/fit/refine_primitive.h"
#include "test_fit_data.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace primitive_edit;
using namespace primitive_edit::refine_detail;
using namespace test_fit;

namespace {

double full_normal_equations(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w, Mat7* JtJ,
                             Vec7* Jtr)
{
  const LocalFrame frame = local_frame(p);
  JtJ->setZero();
  Jtr->setZero();
  Vec7 J;
  double cost = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    if (!(w[i] > 0))
      continue;
    const double r = residual(p, frame, points.row(i).transpose(), &J);
    const Vec7 wJ = w[i] * J;
    JtJ->noalias() += wJ * J.transpose();
    *Jtr += r * wJ;
    cost += w[i] * r * r;
  }
  return cost;
}

TEST(RefineNormalEquations, TypedBlockEqualsTheFullProductBitForBit)
{
  const std::vector<Primitive> primitives = {
      make_plane({1, -2, 0.5}, {0.3, -0.2, 0.9}),
      make_sphere({0.5, 1, -1}, 2.5),
      make_cylinder({1, 0, 2}, {0.2, 1, 0.3}, 1.5),
      make_cone({0, 0, 0}, {0.1, -0.3, 1}, 0.4),
      make_torus({2, 1, 0}, {0.5, 0.2, 1}, 5, 1.2),
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> box(-4, 4), weight(0.0, 2.0);
  for (const Primitive& p : primitives) {
    SCOPED_TRACE(primitive_type_name(p.type));
    Eigen::MatrixX3d points(300, 3);
    Eigen::VectorXd w(300);
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
      points.row(i) = (p.origin + Eigen::Vector3d(box(rng), box(rng), box(rng))).transpose();
      w[i] = i % 10 == 0 ? 0.0 : weight(rng); // some points left out
    }
    Mat7 typed_JtJ, full_JtJ;
    Vec7 typed_Jtr, full_Jtr;
    const double typed_cost = normal_equations(p, points, w, &typed_JtJ, &typed_Jtr);
    const double full_cost = full_normal_equations(p, points, w, &full_JtJ, &full_Jtr);
    EXPECT_EQ(typed_cost, full_cost);
    for (int a = 0; a < 7; ++a) {
      EXPECT_EQ(typed_Jtr[a], full_Jtr[a]) << "entry " << a;
      for (int b = 0; b < 7; ++b)
        EXPECT_EQ(typed_JtJ(a, b), full_JtJ(a, b)) << "entry " << a << ", " << b;
    }
    const int k = primitive_degrees_of_freedom(p.type);
    EXPECT_GT(typed_JtJ.topLeftCorner(k, k).diagonal().minCoeff(), 0.0);
    if (k < 7) {
      EXPECT_TRUE(typed_JtJ.bottomRows(7 - k).isZero(0.0) && typed_JtJ.rightCols(7 - k).isZero(0.0));
      EXPECT_TRUE(typed_Jtr.tail(7 - k).isZero(0.0));
    }
  }
}

} // namespace
