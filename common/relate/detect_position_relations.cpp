#include "common/relate/detect_position_relations.h"

namespace primitive_edit {

namespace position_detail {

double axis_angle(const Primitive& a, const Primitive& b)
{
  return std::acos(std::min(1.0, std::abs(a.axis.dot(b.axis))));
}

double distance_to_axis(const Primitive& p, const Eigen::Vector3d& x)
{
  return off_axis(p, x - p.origin).norm();
}

Eigen::Vector3d axis_point_facing(const Primitive& p, const Primitive& other)
{
  if (p.type != PrimitiveType::Cone || other.type == PrimitiveType::Cone)
    return p.origin;
  return p.origin + p.axis.dot(other.origin - p.origin) * p.axis;
}

void add_candidate(std::vector<Candidate>& out, double deviation, RelationKind kind, int a, int b,
                   double sign, const Eigen::Vector3d& contact)
{
  if (!(deviation <= 1.0))
    return;
  Relation r;
  r.kind = kind;
  r.a = a;
  r.b = b;
  r.sign = sign;
  r.contact = contact;
  out.push_back({deviation, r});
}

void add_pair_candidates(const Primitive& pa, const Primitive& pb, int a, int b, double max_angle,
                         double max_distance, std::vector<Candidate>& out)
{
  const double ra = relation_radius(pa), rb = relation_radius(pb);
  if (ra > 0 && rb > 0)
    add_candidate(out, std::abs(ra - rb) / max_distance, RelationKind::EqualRadius, a, b);
  if (has_axis(pa) && has_axis(pb)) {
    const double angle = axis_angle(pa, pb);
    const double offset = std::max(distance_to_axis(pa, axis_point_facing(pb, pa)),
                                   distance_to_axis(pb, axis_point_facing(pa, pb)));
    const double sign = pa.axis.dot(pb.axis) < 0 ? -1.0 : 1.0;
    const double deviation = std::max(angle / max_angle, offset / max_distance);
    const bool tori = pa.type == PrimitiveType::Torus && pb.type == PrimitiveType::Torus;
    if (tori && std::abs(pa.axis.dot(pb.origin - pa.origin)) <= max_distance)
      add_candidate(out, std::max(deviation, std::abs(pa.axis.dot(pb.origin - pa.origin)) / max_distance),
                    RelationKind::Concentric, a, b, sign);
    else
      add_candidate(out, deviation, RelationKind::Coaxial, a, b, sign);
  }
  if (pa.type == PrimitiveType::Plane && pb.type == PrimitiveType::Plane) {
    const double offset =
        std::max(std::abs(pa.axis.dot(pb.origin - pa.origin)), std::abs(pb.axis.dot(pa.origin - pb.origin)));
    add_candidate(out, std::max(axis_angle(pa, pb) / max_angle, offset / max_distance), RelationKind::Coplanar, a,
                  b, pa.axis.dot(pb.axis) < 0 ? -1.0 : 1.0);
  }
  // Concentric with a sphere: the sphere is b in the relation (its centre on a's axis or at a's centre).
  for (const auto& [x, y] : {std::pair<int, int>{a, b}, std::pair<int, int>{b, a}}) {
    const Primitive& px = x == a ? pa : pb;
    const Primitive& py = y == a ? pa : pb;
    if (py.type != PrimitiveType::Sphere || (px.type == PrimitiveType::Sphere && x > y))
      continue;
    const bool on_axis = px.type == PrimitiveType::Cylinder || px.type == PrimitiveType::Cone;
    if (px.type == PrimitiveType::Plane)
      continue;
    add_candidate(out, (on_axis ? distance_to_axis(px, py.origin) : (py.origin - px.origin).norm()) / max_distance,
                  RelationKind::Concentric, x, y);
  }
}

void add_tangent_candidate(const Primitive& pf, const Primitive& pg, int f, int g,
                           const Eigen::Vector3d& contact_point, double max_angle, double max_distance,
                           std::vector<Candidate>& out)
{
  if (pf.type != PrimitiveType::Cylinder && pf.type != PrimitiveType::Torus)
    return;
  if (pf.type == PrimitiveType::Cylinder && pg.type == PrimitiveType::Cylinder && pf.radius > pg.radius)
    return;  // of two cylinders, the thinner rounds the other
  bool aligned = false;
  if (pf.type == PrimitiveType::Cylinder)
    aligned = pg.type == PrimitiveType::Plane ? std::abs(pf.axis.dot(pg.axis)) <= std::sin(max_angle)
              : (pg.type == PrimitiveType::Cylinder || pg.type == PrimitiveType::Cone) && axis_angle(pf, pg) <= max_angle;
  else
    aligned = pg.type == PrimitiveType::Plane ? axis_angle(pf, pg) <= max_angle
              : has_axis(pg) && axis_angle(pf, pg) <= max_angle && distance_to_axis(pg, pf.origin) <= max_distance;
  if (!aligned)
    return;
  const Eigen::Vector3d spine = fillet_spine_point(pf, contact_point);
  const double d = project_onto_primitive(pg, spine).signed_distance;
  add_candidate(out, std::abs(std::abs(d) - relation_radius(pf)) / max_distance, RelationKind::Tangent, f, g,
                d < 0 ? -1.0 : 1.0, contact_point);
}

std::vector<Relation> affordable_candidates(std::vector<Candidate> candidates,
                                            const std::vector<const Primitive*>& primitives,
                                            const std::vector<FitInformation>& info, double max_cost_increase,
                                            double length)
{
  const int count = int(primitives.size());
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.deviation < y.deviation; });
  std::vector<Primitive> p(static_cast<std::size_t>(count));
  for (int s = 0; s < count; ++s)
    if (primitives[std::size_t(s)])
      p[std::size_t(s)] = *primitives[std::size_t(s)];
  const std::vector<char> fixed(std::size_t(count), 0);
  constexpr int kKinds = int(RelationKind::Tangent) + 1;
  std::vector<std::vector<int>> parent(kKinds, std::vector<int>(std::size_t(count)));
  for (auto& forest : parent)
    std::iota(forest.begin(), forest.end(), 0);
  std::vector<Relation> out;
  for (const Candidate& candidate : candidates) {
    const Relation& r = candidate.relation;
    std::vector<int>& forest = parent[std::size_t(int(r.kind))];
    const int x = find_root(forest, r.a), y = find_root(forest, r.b);
    if (x == y && r.kind != RelationKind::Tangent)
      continue;
    const std::vector<double> rise = relation_cost_increase({r}, p, info, fixed, length);
    bool ok = true;
    for (int s : {r.a, r.b}) {
      const FitInformation& fi = info[std::size_t(s)];
      ok = ok && rise[std::size_t(s)] <= max_cost_increase * fi.cost + round_off_cost(length, fi.weight);
    }
    if (!ok)
      continue;
    forest[std::size_t(x)] = y;
    out.push_back(r);
  }
  return out;
}

} // namespace position_detail

std::vector<Relation> detect_position_relations(const std::vector<const Primitive*>& primitives,
                                                const std::vector<FitInformation>& info,
                                                const std::vector<SegmentContact>& contacts, double max_angle,
                                                double max_distance, double max_cost_increase, double length)
{
  using namespace position_detail;
  const int count = int(primitives.size());
  std::vector<Candidate> candidates;
  for (int a = 0; a < count; ++a)
    for (int b = a + 1; b < count; ++b)
      if (primitives[std::size_t(a)] && primitives[std::size_t(b)])
        add_pair_candidates(*primitives[std::size_t(a)], *primitives[std::size_t(b)], a, b, max_angle, max_distance,
                            candidates);
  for (const SegmentContact& c : contacts) {
    if (c.a < 0 || c.b < 0 || c.a == c.b || c.a >= count || c.b >= count || !primitives[std::size_t(c.a)] ||
        !primitives[std::size_t(c.b)])
      continue;
    for (const auto& [f, g] : {std::pair<int, int>{c.a, c.b}, std::pair<int, int>{c.b, c.a}})
      add_tangent_candidate(*primitives[std::size_t(f)], *primitives[std::size_t(g)], f, g, c.point, max_angle,
                            max_distance, candidates);
  }
  return affordable_candidates(std::move(candidates), primitives, info, max_cost_increase, length);
}

} // namespace primitive_edit
