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

std::vector<double> relation_cost_increase(const std::vector<Relation>& relations,
                                           const std::vector<Primitive>& p,
                                           const std::vector<FitInformation>& info,
                                           const std::vector<char>& fixed, double length);

} // namespace primitive_edit

#endif
