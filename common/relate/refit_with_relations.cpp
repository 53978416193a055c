#include "common/relate/refit_with_relations.h"

namespace primitive_edit {

namespace relate_detail {

double part_size(const std::vector<RelatedSegment>& segments)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const RelatedSegment& s : segments)
    for (Eigen::Index i = 0; i < s.points.rows(); ++i) {
      lo = lo.cwiseMin(s.points.row(i).transpose());
      hi = hi.cwiseMax(s.points.row(i).transpose());
    }
  const double size = (hi - lo).norm();
  return std::isfinite(size) && size > 0 ? size : 1.0;
}

Eigen::VectorXd weights_of(const RelatedSegment& s)
{
  return s.weights.size() == s.points.rows() ? s.weights : Eigen::VectorXd::Ones(s.points.rows());
}

double weighted_rms(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w)
{
  double sum = 0, sum_w = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (w[i] > 0) {
      const double d = project_onto_primitive(p, points.row(i).transpose()).signed_distance;
      sum += w[i] * d * d;
      sum_w += w[i];
    }
  return sum_w > 0 ? std::sqrt(sum / sum_w) : 0.0;
}

int relation_unknowns(const std::vector<RelatedSegment>& segments, const std::vector<Relation>& relations,
                      std::vector<int>& offset)
{
  offset.assign(segments.size(), -1);
  int n = 0;
  for (const Relation& r : relations)
    for (int s : {r.a, r.b})
      if (!segments[std::size_t(s)].fixed && offset[std::size_t(s)] < 0) {
        offset[std::size_t(s)] = n;
        n += primitive_degrees_of_freedom(segments[std::size_t(s)].primitive.type);
      }
  return n;
}

bool relations_name_valid_segments(const std::vector<RelatedSegment>& segments,
                                   const std::vector<Relation>& relations)
{
  const int count = int(segments.size());
  for (const Relation& r : relations)
    if (r.a < 0 || r.b < 0 || r.a >= count || r.b >= count || r.a == r.b ||
        !primitive_is_valid(segments[std::size_t(r.a)].primitive) ||
        !primitive_is_valid(segments[std::size_t(r.b)].primitive))
      return false;
  return true;
}

double relation_data_term(const std::vector<RelatedSegment>& segments,
                          const std::vector<Eigen::VectorXd>& weights, const std::vector<int>& offset,
                          const std::vector<Primitive>& q, std::vector<StepBlock>& blocks, int threads)
{
  using namespace refine_detail;
  std::vector<double> cost_of(segments.size(), 0.0);
  std::vector<StepBlock> block_of(segments.size());
  parallel_for(segments.size(), threads, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t s = begin; s < end; ++s) {
      if (offset[s] < 0)
        continue;
      Mat7 JtJ;
      Vec7 Jtr;
      cost_of[s] = normal_equations(q[s], segments[s].points, weights[s], &JtJ, &Jtr);
      const int k = primitive_degrees_of_freedom(q[s].type);
      block_of[s] = {JtJ.topLeftCorner(k, k), Jtr.head(k), offset[s]};
    }
  });
  double cost = 0;
  blocks.clear();
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (offset[s] >= 0) {
      cost += cost_of[s];
      blocks.push_back(std::move(block_of[s]));
    }
  return cost;
}

bool apply_relation_step(const std::vector<Primitive>& p, const std::vector<int>& offset,
                         const Eigen::VectorXd& delta, std::vector<Primitive>& trial)
{
  using namespace refine_detail;
  trial = p;
  for (std::size_t s = 0; s < p.size(); ++s) {
    if (offset[s] < 0)
      continue;
    const Primitive& base = p[s];
    const Eigen::Vector3d e1 = any_orthogonal(base.axis), e2 = base.axis.cross(e1);
    Vec7 d = Vec7::Zero();
    d.head(primitive_degrees_of_freedom(base.type)) = delta.segment(offset[s], primitive_degrees_of_freedom(base.type));
    if (!apply_step(base, e1, e2, d, &trial[s]))
      return false;
  }
  return true;
}

} // namespace relate_detail

RelationRefit refit_with_relations(const std::vector<RelatedSegment>& segments,
                                   const std::vector<Relation>& relations,
                                   int max_iterations,
                                   int threads)
{
  using namespace relate_detail;
  RelationRefit out;
  const int count = int(segments.size());
  for (const RelatedSegment& s : segments)
    out.primitives.push_back(s.primitive);
  std::vector<Eigen::VectorXd> weights;
  for (const RelatedSegment& s : segments)
    weights.push_back(weights_of(s));
  auto finish = [&]() {
    for (int s = 0; s < count; ++s)
      out.rms.push_back(weighted_rms(out.primitives[std::size_t(s)], segments[std::size_t(s)].points,
                                     weights[std::size_t(s)]));
    return out;
  };
  if (!relations_name_valid_segments(segments, relations)) {
    out.status = Status::failure("a relation names a segment without a valid primitive");
    return finish();
  }
  std::vector<int> offset;
  const int n = relation_unknowns(segments, relations, offset);
  if (relations.empty())
    return finish();
  const double length = part_size(segments);
  // Aimed at, and enough: 1e-6 and 1e-4 mm on a 100 mm part (nearly dependent relations may stop short of
  // the aim where the pseudo-inverse cuts their multipliers).
  const double violation_tolerance = 1e-8 * length, violation_enough = 1e-6 * length;

  std::vector<Primitive>& p = out.primitives;
  // A second thread pays for its start (tens of microseconds a step) only on many points.
  Eigen::Index points = 0;
  for (std::size_t s = 0; s < segments.size(); ++s)
    points += offset[s] >= 0 ? segments[s].points.rows() : 0;
  const int data_threads = points >= kParallelRelationPoints ? threads : 1;
  auto data_term = [&](const std::vector<Primitive>& q, std::vector<StepBlock>& blocks) {
    return relation_data_term(segments, weights, offset, q, blocks, data_threads);
  };

  std::vector<StepBlock> blocks;
  double cost = data_term(p, blocks);
  RelationLayout layout = relation_layout(relations, p);
  Eigen::VectorXd c = relation_values(relations, p, layout, length);
  double violation = c.cwiseAbs().maxCoeff();
  double lambda = 1e-6;
  bool done = false;
  // No unknowns (every related segment fixed): nothing to move, only the check below.
  for (out.iterations = 0; out.iterations < max_iterations && !done && n > 0; ++out.iterations) {
    const Eigen::MatrixXd C = relation_jacobian(relations, p, layout, offset, n, length);
    bool accepted = false;
    for (int attempt = 0; attempt < 8 && !accepted; ++attempt, lambda *= 10) {
      const Eigen::VectorXd delta = constrained_step(blocks, C, c, lambda);
      if (delta.size() != n)
        continue;
      std::vector<Primitive> trial;
      if (!apply_relation_step(p, offset, delta, trial))
        continue;
      std::vector<StepBlock> trial_blocks;
      const double trial_cost = data_term(trial, trial_blocks);
      const double trial_violation = relation_values(relations, trial, layout, length).cwiseAbs().maxCoeff();
      // Feasibility first; once feasible, the cost may fall as long as feasibility is kept.
      const bool feasibility = violation > violation_tolerance && trial_violation < 0.5 * violation;
      const bool better = trial_cost < cost && trial_violation <= std::max(violation, violation_tolerance);
      if (!feasibility && !better)
        continue;
      done = !feasibility && cost - trial_cost <= 1e-6 * cost && trial_violation <= violation_enough;
      p = trial;
      cost = trial_cost;
      blocks = std::move(trial_blocks);
      layout = relation_layout(relations, p);
      c = relation_values(relations, p, layout, length);
      violation = c.cwiseAbs().maxCoeff();
      lambda = std::max(lambda * 0.01, 1e-12);  // times 10 by the loop
      accepted = true;
    }
    if (!accepted)
      break;
  }
  out.max_violation = violation;
  if (!(violation <= violation_enough)) {
    out.status = Status::failure("the relations cannot all hold together (largest violation " +
                                 std::to_string(violation) + ")");
    for (int s = 0; s < count; ++s)
      p[std::size_t(s)] = segments[std::size_t(s)].primitive;
    return finish();
  }
  for (int s = 0; s < count; ++s)
    if (offset[std::size_t(s)] >= 0)
      p[std::size_t(s)] = canonicalize_primitive(p[std::size_t(s)], segments[std::size_t(s)].points, weights[std::size_t(s)]);
  return finish();
}

} // namespace primitive_edit
