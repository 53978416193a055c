// relation_jacobian.h: the values of a set of relations and their derivatives with respect to the local
// parameters of the primitives they join (refine_primitive.h's parametrisation: shifts, turns of the
// axis, sizes), for a refit or a test of the relations.
//
// Input:  the relations (relation.h), the primitive of every segment, the first unknown of each segment
//         (-1: the segment is held fixed), the number of unknowns n, and the part's size (relation_residual's
//         `length`). relation_layout gives the rows and frames for a set of relations at the primitives.
// Output: c (m values, all 0 when every relation holds) and C (m x n), by central differences of step
//         1e-6 in each local parameter (one-sided where a step would leave the valid domain).
// Cost:   O(R * 14) relation evaluations for R relations.
#ifndef PRIMITIVE_EDIT_RELATION_JACOBIAN_H
#define PRIMITIVE_EDIT_RELATION_JACOBIAN_H

#include "common/fit/refine_primitive.h"
#include "common/relate/relation.h"

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace primitive_edit {

// Where each relation's components start, their total, and the frames they are measured in.
struct RelationLayout
{
  std::vector<int> row;
  std::vector<RelationFrame> frame;
  int rows = 0;
};

RelationLayout relation_layout(const std::vector<Relation>& relations, const std::vector<Primitive>& p);

Eigen::VectorXd relation_values(const std::vector<Relation>& relations, const std::vector<Primitive>& p,
                                const RelationLayout& layout, double length);

Eigen::MatrixXd relation_jacobian(const std::vector<Relation>& relations, const std::vector<Primitive>& p,
                                  const RelationLayout& layout, const std::vector<int>& offset, int n,
                                  double length);

} // namespace primitive_edit

#endif
