#include "common/relate/relation_jacobian.h"

namespace primitive_edit {

RelationLayout relation_layout(const std::vector<Relation>& relations, const std::vector<Primitive>& p)
{
  RelationLayout out;
  for (const Relation& r : relations) {
    out.row.push_back(out.rows);
    out.rows += relation_components(r, p[std::size_t(r.a)], p[std::size_t(r.b)]);
    out.frame.push_back(relation_frame(p[std::size_t(r.a)]));
  }
  return out;
}

Eigen::VectorXd relation_values(const std::vector<Relation>& relations, const std::vector<Primitive>& p,
                                const RelationLayout& layout, double length)
{
  Eigen::VectorXd c(layout.rows);
  for (std::size_t r = 0; r < relations.size(); ++r)
    relation_residual(relations[r], p[std::size_t(relations[r].a)], p[std::size_t(relations[r].b)], layout.frame[r],
                      length, c.data() + layout.row[r]);
  return c;
}

Eigen::MatrixXd relation_jacobian(const std::vector<Relation>& relations, const std::vector<Primitive>& p,
                                  const RelationLayout& layout, const std::vector<int>& offset, int n,
                                  double length)
{
  using namespace refine_detail;
  constexpr double h = 1e-6;  // local parameters are shifts (mesh units) and turns (radians)
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(layout.rows, n);
  std::vector<Primitive> q = p;
  double base_value[5], plus[5], minus[5];
  for (std::size_t r = 0; r < relations.size(); ++r) {
    const Relation& rel = relations[r];
    const int k = relation_components(rel, p[std::size_t(rel.a)], p[std::size_t(rel.b)]);
    relation_residual(rel, p[std::size_t(rel.a)], p[std::size_t(rel.b)], layout.frame[r], length, base_value);
    for (int s : {rel.a, rel.b}) {
      const int o = offset[std::size_t(s)];
      if (o < 0)
        continue;
      const Primitive& base = p[std::size_t(s)];
      const Eigen::Vector3d e1 = any_orthogonal(base.axis), e2 = base.axis.cross(e1);
      for (int j = 0; j < primitive_degrees_of_freedom(base.type); ++j) {
        double span = 0;
        for (const double sign : {1.0, -1.0}) {
          Vec7 step = Vec7::Zero();
          step[j] = sign * h;
          double* out = sign > 0 ? plus : minus;
          Primitive moved;
          if (apply_step(base, e1, e2, step, &moved)) {
            q[std::size_t(s)] = moved;
            relation_residual(rel, q[std::size_t(rel.a)], q[std::size_t(rel.b)], layout.frame[r], length, out);
            span += h;
          } else {
            std::copy(base_value, base_value + k, out);
          }
        }
        q[std::size_t(s)] = base;
        if (span > 0)
          for (int i = 0; i < k; ++i)
            C(layout.row[r] + i, o + j) = (plus[i] - minus[i]) / span;
      }
    }
  }
  return C;
}

} // namespace primitive_edit
