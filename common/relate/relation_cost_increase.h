// relation_cost_increase.h: what making some relations hold would cost each segment's fit, to first order.
//
// Input:  relations (relation.h), every segment's primitive (at its least-squares fit), its FitInformation
//         (fit_information.h), which segments are held fixed, and the part's size.
// Output: per segment (indexed like the primitives), the rise of its fit cost sum w d^2 when the primitives
//         move by the least-cost step that makes the relations hold (their linearisation), the other
//         parameters of the segments free; 0 for segments in no relation. A relation the data contradicts
//         costs some segment much more than its roughness does; one the data cannot tell from its fit costs
//         little. Infinity for every segment when the step cannot be computed.
// Method: the linearised constrained least squares of constrained_step.h with the fits' normal matrices
//         and zero gradients (each fit is at its minimum): d = -H^-1 C^T (C H^-1 C^T)^+ c; segment s pays
//         d_s^T H_s d_s.
// Cost:   that of one constrained_step over the segments in the relations.
#ifndef PRIMITIVE_EDIT_RELATION_COST_INCREASE_H
#define PRIMITIVE_EDIT_RELATION_COST_INCREASE_H

#include "common/relate/constrained_step.h"
#include "common/relate/fit_information.h"
#include "common/relate/relation_jacobian.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace primitive_edit {

inline std::vector<double> relation_cost_increase(const std::vector<Relation>& relations,
                                                  const std::vector<Primitive>& p,
                                                  const std::vector<FitInformation>& info,
                                                  const std::vector<char>& fixed, double length)
{
  std::vector<double> out(p.size(), 0.0);
  std::vector<int> offset(p.size(), -1);
  std::vector<StepBlock> blocks;
  int n = 0;
  for (const Relation& r : relations)
    for (int s : {r.a, r.b})
      if (!fixed[std::size_t(s)] && offset[std::size_t(s)] < 0) {
        offset[std::size_t(s)] = n;
        const Eigen::MatrixXd& H = info[std::size_t(s)].H;
        blocks.push_back({H, Eigen::VectorXd::Zero(H.rows()), n});
        n += int(H.rows());
      }
  if (n == 0)
    return out;
  const RelationLayout layout = relation_layout(relations, p);
  const Eigen::MatrixXd C = relation_jacobian(relations, p, layout, offset, n, length);
  const Eigen::VectorXd d = constrained_step(blocks, C, relation_values(relations, p, layout, length), 0.0);
  for (const StepBlock& b : blocks) {
    const int s = int(std::find(offset.begin(), offset.end(), b.offset) - offset.begin());
    out[std::size_t(s)] = d.size() == n ? d.segment(b.offset, b.H.rows()).dot(b.H * d.segment(b.offset, b.H.rows()))
                                        : std::numeric_limits<double>::infinity();
  }
  return out;
}

} // namespace primitive_edit

#endif
