// detect_direction_relations.h: which plane normals and axes of a part are parallel, and the part's frame:
// three perpendicular directions that most of them follow, with the 45-degree diagonals between them.
//
// Input:  per segment its fitted primitive (nullptr: none, free-form) and FitInformation (fit_information.h);
//         the largest angle a direction may be off a relation (radians), and the largest share
//         `max_cost_increase` by which a relation may raise a segment's fit cost (to first order).
// Output: Parallel relations (from the strongest member of each class of parallel directions to the others)
//         and, between the frame's classes, an independent set of Perpendicular and Angle (45 or 60 degrees)
//         relations (frame_relations). Every relation was
//         tested on every segment it moves: turning a segment's direction onto the class's direction must cost
//         less than max_cost_increase of its fit cost (plus round-off), onto the frame's less than twice that
//         (DirectionTests), measured with the segment's direction information, so that a strip too narrow to
//         hold its own tilt follows the part, while a large face at a deliberate angle, which the tilt would cost
//         far more than its roughness, does not.
// Method: 1. Classes (parallel_classes): pairs of directions closest to parallel first, two classes merge when
//            every member passes the test against the merged class's direction (the mean weighted by each
//            member's information over its allowed cost rise, by Gauss-Newton: an exact face is not turned, a
//            rough one follows), so that errors cannot creep along a chain of nearly parallel pairs.
//         2. Frame (fit_frame): the strongest class (most direction information) and the strongest one
//            perpendicular to it within the angle span it; a class within the angle of an axis or a diagonal
//            follows it while all its members pass the test against it; the members of the other classes are
//            tested one by one (a class of weak directions tilted together by the roughness, e.g. a boss's short
//            cone band and small fillets 10 degrees off on the bundled scan, holds members whose own direction is
//            near the frame; one failing slot wall would take two large walls parallel to it out). The frame's
//            rotation is fitted to all the members that follow it (Gauss-Newton on 3 angles), until nothing
//            changes; every member left in the frame passes against the final one.
//         3. The segments off the frame form classes again (step 1 among themselves); each frame direction's
//            segments are one class.
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
double turn_cost(const FitInformation& info, const Eigen::Vector3d& dir, Eigen::Vector3d target, double* angle);

// The direction that turns the members least, each in its information metric divided by the cost it may
// take (`allowance`, per segment), so that a member fitted exactly is not turned and a rough one follows
// (Gauss-Newton from `start`).
Eigen::Vector3d mean_direction(const std::vector<Member>& members, const std::vector<FitInformation>& info,
                               const std::vector<double>& allowance, Eigen::Vector3d d);

// The three axes of a rotation, and the directions of a frame: the axes and the diagonals between them.
std::vector<Eigen::Vector3d> frame_directions(const Eigen::Matrix3d& R);

// The tests a direction must pass to follow a class's or the frame's, per segment.
struct DirectionTests
{
  const std::vector<const Primitive*>* primitives;
  const std::vector<FitInformation>* info;
  std::vector<double> allowance;  // the cost a segment may take (mean_direction's weights)
  std::vector<double> floor;      // round_off_cost: a relation that holds to round-off always passes
  double max_angle, max_cost_increase;

  Eigen::Vector3d axis(int s) const { return (*primitives)[std::size_t(s)]->axis; }
  // A class's direction, fitted to its members only, may cost each max_cost_increase; the frame's, fitted to
  // all the faces that follow it, twice that, what the check after the joint refit allows a segment
  // (relate_primitives.h): a face that a wrong segmentation tilted (a plane that took in a countersink's band)
  // then follows the frame instead of pairing off with another tilted one.
  bool follows(const Member& m, const Eigen::Vector3d& target) const { return within(m, target, max_cost_increase); }
  bool follows_frame(const Member& m, const Eigen::Vector3d& target) const
  {
    return within(m, target, 2 * max_cost_increase);
  }
  bool within(const Member& m, const Eigen::Vector3d& target, double cost_increase) const
  {
    const FitInformation& fi = (*info)[std::size_t(m.segment)];
    double angle = 0;
    const double cost = turn_cost(fi, m.dir, target, &angle);
    return angle <= max_angle && cost <= cost_increase * fi.cost + floor[std::size_t(m.segment)];
  }
};

struct ParallelClass
{
  std::vector<Member> members;
  Eigen::Vector3d dir;
};

// Step 1: classes of parallel directions among `segments`, in the order of their first member.
std::vector<ParallelClass> parallel_classes(const std::vector<int>& segments, const DirectionTests& tests);

// The frame direction nearest d within the angle, -1: none.
int nearest_frame_direction(const std::vector<Eigen::Vector3d>& frame, const Eigen::Vector3d& d,
                            double max_angle);

// Turns the frame R to fit the directions of the segments that follow it (Gauss-Newton on a small rotation w).
void fit_frame_rotation(const std::vector<ParallelClass>& classes, const std::vector<int>& target,
                        const std::vector<FitInformation>& info, Eigen::Matrix3d& R);

// Step 2: the frame (R) and the frame direction (frame_directions' index) each segment follows, -1: none; an
// empty vector when the part has no frame.
std::vector<int> fit_frame(const std::vector<ParallelClass>& classes, const DirectionTests& tests,
                           Eigen::Matrix3d& R);

// The member whose direction the points hold most firmly.
int strongest_member(const std::vector<int>& segments, const std::vector<FitInformation>& info);

// Parallel relations from the strongest member of a group to each other member; returns that member.
int add_parallel_relations(const std::vector<int>& group, const DirectionTests& tests,
                           std::vector<Relation>& out);

// Perpendicular and Angle (45 or 60 degrees) relations between the representatives of the frame directions
// `frame_target` (indices into `dirs`, the frame's directions), taken greedily, perpendicular pairs first, each
// only when it is independent at the frame of those taken (its first-order row keeps 30% of its length once theirs
// are projected out): at most 2 m - 3 for m directions, fewer where no pair holds a turn (a diagonal whose plane's
// third axis has no segment may tilt out of that plane). Every pair would over-determine the directions, and a
// diagonal held at 45 degrees to both axes of its plane is held by two constraints tangent to each other there, so
// that the joint refit's step diverges (1M-face bracket scan: every relation dropped).
std::vector<Relation> frame_relations(const std::vector<Eigen::Vector3d>& dirs, const std::vector<int>& frame_target,
                                      const std::vector<int>& representative, const DirectionTests& tests);

} // namespace direction_detail

std::vector<Relation> detect_direction_relations(const std::vector<const Primitive*>& primitives,
                                                 const std::vector<FitInformation>& info, double max_angle,
                                                 double max_cost_increase, double length);

} // namespace primitive_edit

#endif
