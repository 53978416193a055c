#include "common/relate/detect_direction_relations.h"

#include "common/base/constants.h"

namespace primitive_edit {

namespace direction_detail {

double turn_cost(const FitInformation& info, const Eigen::Vector3d& dir, Eigen::Vector3d target, double* angle)
{
  if (target.dot(dir) < 0)
    target = -target;
  const Eigen::Vector3d t = target - dir;
  const Eigen::Vector2d phi(info.e1.dot(t), info.e2.dot(t));
  if (angle)
    *angle = std::acos(std::min(1.0, std::abs(target.normalized().dot(dir))));
  return phi.dot(info.direction * phi);
}

Eigen::Vector3d mean_direction(const std::vector<Member>& members, const std::vector<FitInformation>& info,
                               const std::vector<double>& allowance, Eigen::Vector3d d)
{
  for (int it = 0; it < 4; ++it) {
    const Eigen::Vector3d f1 = any_orthogonal(d), f2 = d.cross(f1);
    Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    for (const Member& m : members) {
      const FitInformation& fi = info[std::size_t(m.segment)];
      Eigen::Matrix<double, 2, 2> P;  // d(phi)/d(psi): the member's turn coordinates of a turn of d
      P << fi.e1.dot(f1), fi.e1.dot(f2), fi.e2.dot(f1), fi.e2.dot(f2);
      const Eigen::Vector3d dev = d - m.dir;
      const Eigen::Vector2d phi(fi.e1.dot(dev), fi.e2.dot(dev));
      const double scale = 1.0 / allowance[std::size_t(m.segment)];
      A += scale * P.transpose() * fi.direction * P;
      b += scale * P.transpose() * fi.direction * phi;
    }
    const double trace = A.trace();
    if (!(trace > 0))
      return d;
    A.diagonal().array() += 1e-12 * trace;
    const Eigen::Vector2d psi = -A.ldlt().solve(b);
    if (!psi.allFinite())
      return d;
    d = (d + psi[0] * f1 + psi[1] * f2).normalized();
  }
  return d;
}

std::vector<Eigen::Vector3d> frame_directions(const Eigen::Matrix3d& R)
{
  std::vector<Eigen::Vector3d> out = {R.col(0), R.col(1), R.col(2)};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      out.push_back((R.col(i) + R.col(j)).normalized());
      out.push_back((R.col(i) - R.col(j)).normalized());
    }
  return out;
}

std::vector<ParallelClass> parallel_classes(const std::vector<int>& segments, const DirectionTests& tests)
{
  std::vector<int> class_of(tests.primitives->size(), -1);
  std::vector<ParallelClass> classes;
  std::vector<int> version;  // changes when a class changes, so that a failed pair of classes is retried then
  for (int s : segments) {
    class_of[std::size_t(s)] = int(classes.size());
    classes.push_back({{{s, tests.axis(s)}}, tests.axis(s)});
    version.push_back(0);
  }
  std::vector<std::tuple<double, int, int>> pairs;
  for (std::size_t i = 0; i < segments.size(); ++i)
    for (std::size_t j = i + 1; j < segments.size(); ++j) {
      const double angle =
          std::acos(std::min(1.0, std::abs(tests.axis(segments[i]).dot(tests.axis(segments[j])))));
      if (angle <= tests.max_angle)
        pairs.emplace_back(angle, segments[i], segments[j]);
    }
  std::sort(pairs.begin(), pairs.end());
  std::vector<std::array<int, 4>> failed;  // class x, version, class y, version
  for (const auto& [angle, a, b] : pairs) {
    const int x = class_of[std::size_t(a)], y = class_of[std::size_t(b)];
    if (x == y)
      continue;
    const std::array<int, 4> key = {std::min(x, y), version[std::size_t(std::min(x, y))], std::max(x, y),
                                     version[std::size_t(std::max(x, y))]};
    if (std::find(failed.begin(), failed.end(), key) != failed.end())
      continue;
    ParallelClass& cx = classes[std::size_t(x)];
    ParallelClass& cy = classes[std::size_t(y)];
    std::vector<Member> both = cx.members;
    const double flip = cx.dir.dot(cy.dir) < 0 ? -1.0 : 1.0;
    for (const Member& m : cy.members)
      both.push_back({m.segment, flip * m.dir});
    const Eigen::Vector3d d = mean_direction(both, *tests.info, tests.allowance, cx.dir);
    if (!std::all_of(both.begin(), both.end(), [&](const Member& m) { return tests.follows(m, d); })) {
      failed.push_back(key);
      continue;
    }
    for (const Member& m : cy.members)
      class_of[std::size_t(m.segment)] = x;
    cx.members = both;
    cx.dir = d;
    cy.members.clear();
    ++version[std::size_t(x)];
    ++version[std::size_t(y)];
  }
  classes.erase(std::remove_if(classes.begin(), classes.end(),
                               [](const ParallelClass& c) { return c.members.empty(); }),
                classes.end());
  return classes;
}

int nearest_frame_direction(const std::vector<Eigen::Vector3d>& frame, const Eigen::Vector3d& d,
                            double max_angle)
{
  int nearest = -1;
  double best = max_angle;
  for (std::size_t t = 0; t < frame.size(); ++t) {
    const double angle = std::acos(std::min(1.0, std::abs(frame[t].dot(d))));
    if (angle <= best) {
      best = angle;
      nearest = int(t);
    }
  }
  return nearest;
}

void fit_frame_rotation(const std::vector<ParallelClass>& classes, const std::vector<int>& target,
                        const std::vector<FitInformation>& info, Eigen::Matrix3d& R)
{
  for (int it = 0; it < 4; ++it) {
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    const std::vector<Eigen::Vector3d> dirs = frame_directions(R);
    for (const ParallelClass& c : classes)
      for (const Member& m : c.members) {
        if (target[std::size_t(m.segment)] < 0)
          continue;
        const Eigen::Vector3d& u = dirs[std::size_t(target[std::size_t(m.segment)])];
        const FitInformation& fi = info[std::size_t(m.segment)];
        const Eigen::Vector3d ut = u.dot(m.dir) < 0 ? Eigen::Vector3d(-u) : u;
        // d(ut)/dw = -[ut]x: the member's turn coordinates of a frame rotation w.
        Eigen::Matrix<double, 2, 3> P;
        P.row(0) = ut.cross(fi.e1).transpose();
        P.row(1) = ut.cross(fi.e2).transpose();
        const Eigen::Vector3d dev = ut - m.dir;
        const Eigen::Vector2d phi(fi.e1.dot(dev), fi.e2.dot(dev));
        A += P.transpose() * fi.direction * P;
        b += P.transpose() * fi.direction * phi;
      }
    const double trace = A.trace();
    if (!(trace > 0))
      return;
    A.diagonal().array() += 1e-9 * trace;  // a rotation about a single assigned axis is free: keep it still
    const Eigen::Vector3d w = -A.ldlt().solve(b);
    if (!w.allFinite())
      return;
    const double angle = w.norm();
    if (angle > 0)
      R = Eigen::AngleAxisd(angle, w / angle).toRotationMatrix() * R;
  }
}

std::vector<int> fit_frame(const std::vector<ParallelClass>& classes, const DirectionTests& tests,
                           Eigen::Matrix3d& R)
{
  std::vector<double> strength(classes.size(), 0.0);
  std::vector<int> order(classes.size());
  std::iota(order.begin(), order.end(), 0);
  for (std::size_t x = 0; x < classes.size(); ++x)
    for (const Member& m : classes[x].members)
      strength[x] += (*tests.info)[std::size_t(m.segment)].direction.trace();
  std::stable_sort(order.begin(), order.end(),
                   [&](int x, int y) { return strength[std::size_t(x)] > strength[std::size_t(y)]; });
  if (order.size() < 2)
    return {};
  const Eigen::Vector3d f1 = classes[std::size_t(order[0])].dir;
  int second = -1;
  for (std::size_t i = 1; i < order.size() && second < 0; ++i)
    if (std::abs(f1.dot(classes[std::size_t(order[i])].dir)) <= std::sin(tests.max_angle))
      second = order[i];
  if (second < 0)
    return {};
  const Eigen::Vector3d& f2 = classes[std::size_t(second)].dir;
  R.col(0) = f1;
  R.col(1) = (f2 - f2.dot(f1) * f1).normalized();
  R.col(2) = R.col(0).cross(R.col(1));

  std::vector<int> target(tests.primitives->size(), -1), class_target(classes.size(), -1), before;
  std::vector<char> excluded(classes.size(), 0);
  for (int round = 0; round < 8; ++round) {
    const std::vector<Eigen::Vector3d> fd = frame_directions(R);
    for (std::size_t x = 0; x < classes.size(); ++x) {
      class_target[x] = excluded[x] ? -1 : nearest_frame_direction(fd, classes[x].dir, tests.max_angle);
      for (const Member& m : classes[x].members) {
        int t = class_target[x];
        if (t < 0) {
          t = nearest_frame_direction(fd, m.dir, tests.max_angle);
          if (t >= 0 && !tests.follows_frame(m, fd[std::size_t(t)]))
            t = -1;
        }
        target[std::size_t(m.segment)] = t;
      }
    }
    fit_frame_rotation(classes, target, *tests.info, R);
    // Classes whose members cannot follow their frame direction leave it (their members are tried alone).
    const std::vector<Eigen::Vector3d> dirs = frame_directions(R);
    bool changed = target != before;
    for (std::size_t x = 0; x < classes.size(); ++x)
      if (class_target[x] >= 0 &&
          !std::all_of(classes[x].members.begin(), classes[x].members.end(),
                       [&](const Member& m) { return tests.follows_frame(m, dirs[std::size_t(class_target[x])]); })) {
        excluded[x] = 1;
        changed = true;
      }
    if (!changed)
      break;
    before = target;
  }
  // Every segment left in the frame passes against the final frame.
  const std::vector<Eigen::Vector3d> dirs = frame_directions(R);
  for (const ParallelClass& c : classes)
    for (const Member& m : c.members) {
      int& t = target[std::size_t(m.segment)];
      if (t >= 0 && !tests.follows_frame(m, dirs[std::size_t(t)]))
        t = -1;
    }
  return target;
}

int strongest_member(const std::vector<int>& segments, const std::vector<FitInformation>& info)
{
  int best = segments.front();
  for (int s : segments)
    if (info[std::size_t(s)].direction.trace() > info[std::size_t(best)].direction.trace())
      best = s;
  return best;
}

int add_parallel_relations(const std::vector<int>& group, const DirectionTests& tests,
                           std::vector<Relation>& out)
{
  const int rep = strongest_member(group, *tests.info);
  for (int s : group) {
    if (s == rep)
      continue;
    Relation r;
    r.kind = RelationKind::Parallel;
    r.a = rep;
    r.b = s;
    r.sign = tests.axis(rep).dot(tests.axis(s)) < 0 ? -1.0 : 1.0;
    out.push_back(r);
  }
  return rep;
}

std::vector<Relation> frame_relations(const std::vector<Eigen::Vector3d>& dirs, const std::vector<int>& frame_target,
                                      const std::vector<int>& representative, const DirectionTests& tests)
{
  const std::size_t m = frame_target.size();
  // Candidates: every pair whose frame directions are perpendicular, 45 or 60 degrees apart, in that order.
  struct Candidate
  {
    std::size_t i, j;
    double angle_deg;
  };
  std::vector<Candidate> candidates;
  for (const double angle_deg : {90.0, 45.0, 60.0})
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = i + 1; j < m; ++j) {
        const double c = std::abs(dirs[std::size_t(frame_target[i])].dot(dirs[std::size_t(frame_target[j])]));
        if (std::abs(c - std::cos(radians_from_degrees(angle_deg))) < 1e-9)
          candidates.push_back({i, j, angle_deg});
      }
  // Each direction's two turns at its frame direction; a relation's row is its first-order change.
  std::vector<Eigen::Vector3d> t1(m), t2(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d& u = dirs[std::size_t(frame_target[i])];
    t1[i] = u.unitOrthogonal();
    t2[i] = u.cross(t1[i]);
  }
  std::vector<Eigen::VectorXd> basis;  // orthonormal rows taken so far
  std::vector<Relation> out;
  for (const Candidate& k : candidates) {
    const Eigen::Vector3d& ui = dirs[std::size_t(frame_target[k.i])];
    const Eigen::Vector3d& uj = dirs[std::size_t(frame_target[k.j])];
    Eigen::VectorXd row = Eigen::VectorXd::Zero(Eigen::Index(2 * m));
    row[Eigen::Index(2 * k.i)] = t1[k.i].dot(uj);
    row[Eigen::Index(2 * k.i + 1)] = t2[k.i].dot(uj);
    row[Eigen::Index(2 * k.j)] = ui.dot(t1[k.j]);
    row[Eigen::Index(2 * k.j + 1)] = ui.dot(t2[k.j]);
    const double norm = row.norm();
    for (const Eigen::VectorXd& q : basis)
      row -= q.dot(row) * q;
    if (!(row.norm() > 0.3 * norm))
      continue;  // implied by the relations taken, to first order: it would only make their step ill-posed
    basis.push_back(row / row.norm());
    Relation r;
    r.a = representative[k.i];
    r.b = representative[k.j];
    if (k.angle_deg == 90.0) {
      r.kind = RelationKind::Perpendicular;
    } else {
      r.kind = RelationKind::Angle;
      r.angle_deg = k.angle_deg;
      // Orient b so that its direction makes the acute angle with a's.
      r.sign = tests.axis(r.a).dot(tests.axis(r.b)) < 0 ? -1.0 : 1.0;
    }
    out.push_back(r);
  }
  return out;
}

} // namespace direction_detail

std::vector<Relation> detect_direction_relations(const std::vector<const Primitive*>& primitives,
                                                 const std::vector<FitInformation>& info, double max_angle,
                                                 double max_cost_increase, double length)
{
  using namespace direction_detail;
  std::vector<Relation> out;
  std::vector<int> directed;
  for (std::size_t s = 0; s < primitives.size(); ++s)
    if (primitives[s] && has_direction(*primitives[s]) && info[s].weight > 0)
      directed.push_back(int(s));
  DirectionTests tests{&primitives, &info, std::vector<double>(primitives.size(), 1.0),
                       std::vector<double>(primitives.size(), 0.0), max_angle, max_cost_increase};
  for (int s : directed) {
    const std::size_t i = std::size_t(s);
    tests.floor[i] = round_off_cost(length, info[i].weight);
    tests.allowance[i] =
        std::max(max_cost_increase * info[i].cost + tests.floor[i], std::numeric_limits<double>::min());
  }

  const std::vector<ParallelClass> classes = parallel_classes(directed, tests);
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  std::vector<int> target = fit_frame(classes, tests, R);
  target.resize(primitives.size(), -1);

  // The segments off the frame form their own classes; each frame direction's segments are one class.
  std::vector<int> off_frame;
  for (int s : directed)
    if (target[std::size_t(s)] < 0)
      off_frame.push_back(s);
  for (const ParallelClass& c : parallel_classes(off_frame, tests)) {
    std::vector<int> group;
    for (const Member& m : c.members)
      group.push_back(m.segment);
    add_parallel_relations(group, tests, out);
  }
  const std::vector<Eigen::Vector3d> dirs = frame_directions(R);
  std::vector<int> frame_target, representative;
  for (int t = 0; t < int(dirs.size()); ++t) {
    std::vector<int> group;
    for (int s : directed)
      if (target[std::size_t(s)] == t)
        group.push_back(s);
    if (group.empty())
      continue;
    frame_target.push_back(t);
    representative.push_back(add_parallel_relations(group, tests, out));
  }
  const std::vector<Relation> held = frame_relations(dirs, frame_target, representative, tests);
  out.insert(out.end(), held.begin(), held.end());
  return out;
}

} // namespace primitive_edit
