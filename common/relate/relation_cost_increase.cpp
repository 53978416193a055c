#include "common/relate/relation_cost_increase.h"

namespace primitive_edit {

std::vector<double> relation_cost_increase(const std::vector<Relation>& relations,
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
