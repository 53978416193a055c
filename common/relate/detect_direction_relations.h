// detect_direction_relations.h: which plane normals and axes of a part are parallel, and the part's frame:
// three perpendicular directions that most of them follow, with the 45-degree diagonals between them.
//
// Input:  per segment its fitted primitive (nullptr: none, free-form) and FitInformation (fit_information.h);
//         the largest angle a direction may be off a relation (radians), and the largest share
//         `max_cost_increase` by which a relation may raise a segment's fit cost (to first order).
// Output: Parallel relations (a spanning tree of each class of parallel directions) and, between the classes
//         that follow the frame, Perpendicular and 45-degree Angle relations. Every relation was tested on
//         every segment it moves: turning a segment's direction onto the class's or frame's direction must
//         cost less than max_cost_increase of its fit cost (plus round-off), measured with the segment's
//         direction information, so that a strip too narrow to hold its own tilt follows the part, while a
//         large face at a deliberate angle, which the tilt would cost far more than its roughness, does not.
// Method: 1. Classes: pairs of directions closest to parallel first, two classes merge when every member
//            passes the test against the merged class's direction (the mean weighted by each member's
//            information over its allowed cost rise, by Gauss-Newton: an exact face is not turned, a rough
//            one follows), so that errors cannot creep along a chain of nearly parallel pairs.
//         2. Frame: the strongest class (most direction information) and the strongest one perpendicular to
//            it within the angle span it; every class within the angle of an axis or a diagonal is assigned
//            to it, the frame's rotation is fitted to all assigned members (Gauss-Newton on 3 angles), and
//            classes whose members fail the test against their frame direction leave it, until none does.
// Cost:   O(D^2 log D) for D directions (pairs sorted), plus O(D) per merge test and per frame round.
#ifndef PRIMITIVE_EDIT_DETECT_DIRECTION_RELATIONS_H
#define PRIMITIVE_EDIT_DETECT_DIRECTION_RELATIONS_H

#include "common/relate/fit_information.h"
#include "common/relate/relation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <vector>

namespace primitive_edit {

namespace direction_detail {

struct Member
{
  int segment;
  Eigen::Vector3d dir;  // the segment's direction, signed like its class
};

// Turning the segment's direction onto `target` (either sign): the first-order cost and the angle.
inline double turn_cost(const FitInformation& info, const Eigen::Vector3d& dir, Eigen::Vector3d target, double* angle)
{
  if (target.dot(dir) < 0)
    target = -target;
  const Eigen::Vector3d t = target - dir;
  const Eigen::Vector2d phi(info.e1.dot(t), info.e2.dot(t));
  if (angle)
    *angle = std::acos(std::min(1.0, std::abs(target.normalized().dot(dir))));
  return phi.dot(info.direction * phi);
}

inline bool passes(const FitInformation& info, const Eigen::Vector3d& dir, const Eigen::Vector3d& target,
                   double max_angle, double max_cost_increase, double floor)
{
  double angle = 0;
  const double cost = turn_cost(info, dir, target, &angle);
  return angle <= max_angle && cost <= max_cost_increase * info.cost + floor;
}

// The direction that turns the members least, each in its information metric divided by the cost it may
// take (`allowance`, per segment), so that a member fitted exactly is not turned and a rough one follows
// (Gauss-Newton from `start`).
inline Eigen::Vector3d mean_direction(const std::vector<Member>& members, const std::vector<FitInformation>& info,
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

// The three axes of a rotation, and the directions of a frame: the axes and the diagonals between them.
inline std::vector<Eigen::Vector3d> frame_directions(const Eigen::Matrix3d& R)
{
  std::vector<Eigen::Vector3d> out = {R.col(0), R.col(1), R.col(2)};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      out.push_back((R.col(i) + R.col(j)).normalized());
      out.push_back((R.col(i) - R.col(j)).normalized());
    }
  return out;
}

} // namespace direction_detail

inline std::vector<Relation> detect_direction_relations(const std::vector<const Primitive*>& primitives,
                                                        const std::vector<FitInformation>& info, double max_angle,
                                                        double max_cost_increase, double length)
{
  using namespace direction_detail;
  std::vector<Relation> out;
  std::vector<int> directed;
  for (std::size_t s = 0; s < primitives.size(); ++s)
    if (primitives[s] && has_direction(*primitives[s]) && info[s].weight > 0)
      directed.push_back(int(s));
  // Round-off of exact data: a relation that holds to 1e-7 of the part's size always passes.
  auto floor_of = [&](int s) { return 1e-14 * length * length * info[std::size_t(s)].weight; };
  auto axis = [&](int s) { return primitives[std::size_t(s)]->axis; };
  std::vector<double> allowance(primitives.size(), 1.0);
  for (int s : directed)
    allowance[std::size_t(s)] =
        std::max(max_cost_increase * info[std::size_t(s)].cost + floor_of(s), std::numeric_limits<double>::min());

  // 1. Classes of parallel directions.
  std::vector<int> class_of(primitives.size(), -1);
  std::vector<std::vector<Member>> members;
  std::vector<Eigen::Vector3d> class_dir;
  std::vector<int> version;  // changes when a class changes, so that a failed pair of classes is retried then
  for (int s : directed) {
    class_of[std::size_t(s)] = int(members.size());
    members.push_back({{s, axis(s)}});
    class_dir.push_back(axis(s));
    version.push_back(0);
  }
  std::vector<std::tuple<double, int, int>> pairs;
  for (std::size_t i = 0; i < directed.size(); ++i)
    for (std::size_t j = i + 1; j < directed.size(); ++j) {
      const double angle = std::acos(std::min(1.0, std::abs(axis(directed[i]).dot(axis(directed[j])))));
      if (angle <= max_angle)
        pairs.emplace_back(angle, directed[i], directed[j]);
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
    std::vector<Member> both = members[std::size_t(x)];
    const double flip = class_dir[std::size_t(x)].dot(class_dir[std::size_t(y)]) < 0 ? -1.0 : 1.0;
    for (const Member& m : members[std::size_t(y)])
      both.push_back({m.segment, flip * m.dir});
    const Eigen::Vector3d d = mean_direction(both, info, allowance, class_dir[std::size_t(x)]);
    bool ok = true;
    for (const Member& m : both)
      ok = ok && passes(info[std::size_t(m.segment)], m.dir, d, max_angle, max_cost_increase, floor_of(m.segment));
    if (!ok) {
      failed.push_back(key);
      continue;
    }
    Relation r;
    r.kind = RelationKind::Parallel;
    r.a = a;
    r.b = b;
    r.sign = axis(a).dot(axis(b)) < 0 ? -1.0 : 1.0;
    out.push_back(r);
    for (const Member& m : members[std::size_t(y)])
      class_of[std::size_t(m.segment)] = x;
    members[std::size_t(x)] = both;
    members[std::size_t(y)].clear();
    class_dir[std::size_t(x)] = d;
    ++version[std::size_t(x)];
    ++version[std::size_t(y)];
  }

  // 2. The frame.
  std::vector<int> classes;
  std::vector<double> strength(members.size(), 0.0);
  for (std::size_t x = 0; x < members.size(); ++x) {
    if (members[x].empty())
      continue;
    for (const Member& m : members[x])
      strength[x] += info[std::size_t(m.segment)].direction.trace();
    classes.push_back(int(x));
  }
  std::stable_sort(classes.begin(), classes.end(),
                   [&](int x, int y) { return strength[std::size_t(x)] > strength[std::size_t(y)]; });
  if (classes.size() < 2)
    return out;
  const Eigen::Vector3d f1 = class_dir[std::size_t(classes[0])];
  int second = -1;
  for (std::size_t i = 1; i < classes.size() && second < 0; ++i)
    if (std::abs(f1.dot(class_dir[std::size_t(classes[i])])) <= std::sin(max_angle))
      second = classes[i];
  if (second < 0)
    return out;
  Eigen::Matrix3d R;
  R.col(0) = f1;
  R.col(1) = (class_dir[std::size_t(second)] - class_dir[std::size_t(second)].dot(f1) * f1).normalized();
  R.col(2) = R.col(0).cross(R.col(1));

  std::vector<int> target(members.size(), -1);  // frame direction index of each class in the frame
  std::vector<char> excluded(members.size(), 0);
  for (int round = 0; round < 8; ++round) {
    // Assign every class to the nearest frame direction within the angle.
    const std::vector<Eigen::Vector3d> fd = frame_directions(R);
    for (int x : classes) {
      target[std::size_t(x)] = -1;
      if (excluded[std::size_t(x)])
        continue;
      double best = max_angle;
      for (std::size_t t = 0; t < fd.size(); ++t) {
        const double angle = std::acos(std::min(1.0, std::abs(fd[t].dot(class_dir[std::size_t(x)]))));
        if (angle <= best) {
          best = angle;
          target[std::size_t(x)] = int(t);
        }
      }
    }
    // Fit the rotation to every member of the assigned classes (Gauss-Newton on a small rotation w).
    for (int it = 0; it < 4; ++it) {
      Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
      Eigen::Vector3d b = Eigen::Vector3d::Zero();
      const std::vector<Eigen::Vector3d> dirs = frame_directions(R);
      for (int x : classes) {
        if (target[std::size_t(x)] < 0)
          continue;
        Eigen::Vector3d u = dirs[std::size_t(target[std::size_t(x)])];
        for (const Member& m : members[std::size_t(x)]) {
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
      }
      const double trace = A.trace();
      if (!(trace > 0))
        break;
      A.diagonal().array() += 1e-9 * trace;  // a rotation about a single assigned axis is free: keep it still
      const Eigen::Vector3d w = -A.ldlt().solve(b);
      if (!w.allFinite())
        break;
      const double angle = w.norm();
      if (angle > 0)
        R = Eigen::AngleAxisd(angle, w / angle).toRotationMatrix() * R;
    }
    // Classes whose members cannot follow their frame direction leave the frame.
    const std::vector<Eigen::Vector3d> dirs = frame_directions(R);
    bool changed = false;
    for (int x : classes) {
      if (target[std::size_t(x)] < 0)
        continue;
      bool ok = true;
      for (const Member& m : members[std::size_t(x)])
        ok = ok && passes(info[std::size_t(m.segment)], m.dir, dirs[std::size_t(target[std::size_t(x)])], max_angle,
                          max_cost_increase, floor_of(m.segment));
      if (!ok) {
        excluded[std::size_t(x)] = 1;
        changed = true;
      }
    }
    if (!changed)
      break;
  }

  // Relations between the representatives (strongest members) of the classes in the frame.
  const std::vector<Eigen::Vector3d> dirs = frame_directions(R);
  std::vector<int> in_frame;
  for (int x : classes)
    if (target[std::size_t(x)] >= 0 && !excluded[std::size_t(x)])
      in_frame.push_back(x);
  auto representative = [&](int x) {
    int best = members[std::size_t(x)].front().segment;
    for (const Member& m : members[std::size_t(x)])
      if (info[std::size_t(m.segment)].direction.trace() > info[std::size_t(best)].direction.trace())
        best = m.segment;
    return best;
  };
  for (std::size_t i = 0; i < in_frame.size(); ++i)
    for (std::size_t j = i + 1; j < in_frame.size(); ++j) {
      const Eigen::Vector3d& u = dirs[std::size_t(target[std::size_t(in_frame[i])])];
      const Eigen::Vector3d& v = dirs[std::size_t(target[std::size_t(in_frame[j])])];
      const double c = u.dot(v);
      Relation r;
      r.a = representative(in_frame[i]);
      r.b = representative(in_frame[j]);
      if (std::abs(c) < 1e-9) {
        r.kind = RelationKind::Perpendicular;
      } else if (std::abs(std::abs(c) - std::sqrt(0.5)) < 1e-9) {
        r.kind = RelationKind::Angle;
        r.angle_deg = 45;
        // Orient b so that its direction makes 45 (not 135) degrees with a's.
        r.sign = axis(r.a).dot(axis(r.b)) < 0 ? -1.0 : 1.0;
      } else {
        continue;  // the same frame direction twice: both classes follow it, no relation between them needed
      }
      out.push_back(r);
    }
  return out;
}

} // namespace primitive_edit

#endif
