#include "common/relate/fit_information.h"

namespace primitive_edit {

int axis_turn_parameter(PrimitiveType type)
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

FitInformation fit_information(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w)
{
  using namespace refine_detail;
  FitInformation out;
  Mat7 JtJ;
  Vec7 Jtr;
  out.cost = normal_equations(p, points, w, &JtJ, &Jtr);
  out.weight = w.sum();
  const int k = primitive_degrees_of_freedom(p.type);
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
