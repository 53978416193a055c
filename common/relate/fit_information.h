// fit_information.h: how firmly a segment's points hold its fitted primitive, per parameter.
//
// Input:  a valid primitive (a segment's least-squares fit), its points N x 3 and weights N (0: not used).
// Output: FitInformation: the normal matrix H = J^T W J of the orthogonal distances in refine_primitive.h's
//         local parameters (so that moving the primitive by the local step d raises the fit's cost
//         sum w d_i^2 by d^T H d, to second order, from its minimum); that cost and the total weight; and
//         the information about the direction alone (plane normal or axis; none for a sphere): the 2 x 2
//         Schur complement of H onto the two turns of the axis (along e1 and e2), every other parameter
//         left free, so that turning the direction by the small angle vector phi (components along e1, e2)
//         costs phi^T direction phi at least. A narrow strip holds its direction firmly along its length
//         and loosely across: the relations (detect_direction_relations.h) weigh it so.
// Cost:   O(N).
#ifndef PRIMITIVE_EDIT_FIT_INFORMATION_H
#define PRIMITIVE_EDIT_FIT_INFORMATION_H

#include "common/fit/refine_primitive.h"

#include <Eigen/Core>
#include <Eigen/LU>

namespace primitive_edit {

struct FitInformation
{
  Eigen::MatrixXd H;     // k x k, refine_primitive.h's local parameters
  double cost = 0;       // sum w d^2 at the primitive
  double weight = 0;     // sum w
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY();  // the turns' directions
  Eigen::Matrix2d direction = Eigen::Matrix2d::Zero();
};

// Index of the first of the two turn parameters of the axis in refine_primitive's local parameters; -1: none.
inline int axis_turn_parameter(PrimitiveType type)
{
  switch (type) {
  case PrimitiveType::Plane: return 1;
  case PrimitiveType::Cylinder: return 2;
  case PrimitiveType::Cone:
  case PrimitiveType::Torus: return 3;
  case PrimitiveType::Sphere: return -1;
  }
  return -1;
}

inline FitInformation fit_information(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w)
{
  using namespace refine_detail;
  FitInformation out;
  Mat7 JtJ;
  Vec7 Jtr;
  out.cost = normal_equations(p, points, w, &JtJ, &Jtr);
  out.weight = w.sum();
  const int k = parameter_count(p.type);
  out.H = JtJ.topLeftCorner(k, k);
  const LocalFrame frame = local_frame(p);
  out.e1 = frame.e1;
  out.e2 = frame.e2;
  const int t = axis_turn_parameter(p.type);
  if (t < 0)
    return out;
  // Schur complement onto the turns: the others (offsets, sizes) re-optimised for each turn.
  Eigen::MatrixXd others(k - 2, k - 2), cross(2, k - 2);
  Eigen::Matrix2d turns = out.H.block<2, 2>(t, t);
  int col = 0;
  for (int j = 0; j < k; ++j) {
    if (j == t || j == t + 1)
      continue;
    int row = 0;
    for (int i = 0; i < k; ++i)
      if (i != t && i != t + 1)
        others(row++, col) = out.H(i, j);
    cross(0, col) = out.H(t, j);
    cross(1, col) = out.H(t + 1, j);
    ++col;
  }
  const double floor = 1e-12 * std::max(others.diagonal().cwiseAbs().maxCoeff(), 1e-300);
  others.diagonal().array() += floor;
  out.direction = turns - cross * others.ldlt().solve(cross.transpose());
  out.direction = 0.5 * (out.direction + out.direction.transpose());
  return out;
}

} // namespace primitive_edit

#endif
