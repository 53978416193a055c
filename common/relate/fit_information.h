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
int axis_turn_parameter(PrimitiveType type);

FitInformation fit_information(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w);

// Round-off of exact data: a fit within 1e-7 of the part's size (length) is exact, and every cost test of the
// relations lets a segment's cost rise by the cost of that distance over its weight (the sum of its weights).
inline double round_off_cost(double length, double weight) { return 1e-14 * length * length * weight; }

} // namespace primitive_edit

#endif
