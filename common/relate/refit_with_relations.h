// refit_with_relations.h: refit the primitives of several segments together, with relations between them
// holding exactly (GlobFit's constrained least squares: Li et al., "GlobFit: Consistently fitting primitives
// by discovering global relations", SIGGRAPH 2011).
//
// Input:  RelatedSegment per segment: its primitive (the start: the segment's own fit), its points and
//         weights (weight 0: not used; e.g. outliers of the segment's own robust fit), and whether it is
//         fixed (held as it is, e.g. a segment already snapped in the edit tool); the relations
//         (relation.h) between segments; the iteration limit; the threads (<= 0: all hardware threads) over which
//         the segments' normal equations are spread from kParallelRelationPoints points on (the result is the
//         same for any count).
// Output: RelationRefit: every segment's primitive (those in no relation, and fixed ones, unchanged), the
//         weighted RMS distance of each segment's points to it, the largest violation of a relation after
//         the refit (in mesh units; angles times the part's size) and the iterations. A failed status when
//         the relations could not be satisfied together within 1e-6 of the part's size (contradictory
//         relations) or a primitive left its valid domain; the primitives are then the starts.
// Method: minimise sum over segments of sum_i w_i d_i^2 (d: the orthogonal distance of refine_primitive.h, in
//         its local parameters re-based after every step) subject to every relation's residual being 0.
//         Each Levenberg-Marquardt step solves the linearised problem exactly: the KKT system of the
//         block-diagonal damped normal matrix A and the relations' Jacobian C (central differences of
//         relation_residual), by the Schur complement S = C A^-1 C^T with a pseudo-inverse, so that
//         redundant relations (three planes mutually perpendicular twice over) are harmless. A step is taken
//         when it halves the largest violation, or lowers the cost without raising the violation.
// Cost:   per step O(N / threads) for the normal equations (N points of the segments in relations), O(R) relation
//         evaluations for the Jacobian (R relations, at most 14 each), and O(m^2 n + m^3) for the Schur
//         complement (m relation components, n <= 7 K unknowns); up to max_iterations steps.
#ifndef PRIMITIVE_EDIT_REFIT_WITH_RELATIONS_H
#define PRIMITIVE_EDIT_REFIT_WITH_RELATIONS_H

#include "common/base/canonicalize_primitive.h"
#include "common/base/parallel_for.h"
#include "common/base/status.h"
#include "common/fit/refine_primitive.h"
#include "common/relate/constrained_step.h"
#include "common/relate/relation.h"
#include "common/relate/relation_jacobian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace primitive_edit {

struct RelatedSegment
{
  Primitive primitive;
  Eigen::MatrixX3d points;
  Eigen::VectorXd weights;  // empty: all 1
  bool fixed = false;
};

struct RelationRefit
{
  Status status;
  std::vector<Primitive> primitives;  // per segment
  std::vector<double> rms;            // per segment, weighted, on its points
  double max_violation = 0;
  int iterations = 0;
};

// The points in relations from which a refit's passes over them are split between threads.
constexpr Eigen::Index kParallelRelationPoints = 20000;
// Levenberg-Marquardt steps a refit takes at most.
constexpr int kRelationRefitIterations = 40;

namespace relate_detail {

// A length that makes angle components comparable with distances: the extent of all points.
double part_size(const std::vector<RelatedSegment>& segments);

Eigen::VectorXd weights_of(const RelatedSegment& s);

double weighted_rms(const Primitive& p, const Eigen::MatrixX3d& points, const Eigen::VectorXd& w);

// The unknowns: the local parameters of every segment in a relation and not fixed (-1: none). Returns n.
int relation_unknowns(const std::vector<RelatedSegment>& segments, const std::vector<Relation>& relations,
                      std::vector<int>& offset);

bool relations_name_valid_segments(const std::vector<RelatedSegment>& segments,
                                   const std::vector<Relation>& relations);

// The data term of the unknown segments at q: its cost and each block's normal equations (one pass: a tried
// step's blocks are the next step's when it is taken). Segments are spread over `threads`, each segment's sums
// taken by one thread and added in segment order, so the result does not depend on the thread count.
double relation_data_term(const std::vector<RelatedSegment>& segments,
                          const std::vector<Eigen::VectorXd>& weights, const std::vector<int>& offset,
                          const std::vector<Primitive>& q, std::vector<StepBlock>& blocks, int threads);

// p moved by the step delta over the unknowns; false when a primitive would leave its valid domain.
bool apply_relation_step(const std::vector<Primitive>& p, const std::vector<int>& offset,
                         const Eigen::VectorXd& delta, std::vector<Primitive>& trial);

} // namespace relate_detail

RelationRefit refit_with_relations(const std::vector<RelatedSegment>& segments,
                                   const std::vector<Relation>& relations,
                                   int max_iterations = kRelationRefitIterations,
                                   int threads = 1);

} // namespace primitive_edit

#endif
