// fit_quadric_direct.h: the paper's direct type-constrained quadric fit for a given type (dispatch to
// fit_plane_direct ... fit_cone_direct).
//
// Input:  the type, points N x 3, weights N or empty (= all 1). Normals are not needed.
// Output: the FitResult of that type's direct fit (see each fit_*_direct.h for the method and the
//         refusals); a torus is not a quadric and is refused.
// Method: Andrews & Sequin, "Type-constrained direct fitting of quadric surfaces", CAD&A 11(1), 2014,
//         as the paper (Yang, Oh, Choi, section 2.2) uses it: the algebraic quadric fit with the type's
//         constraints, Taubin-normalised, on centred and scaled data, parameters read off the quadric.
//         No geometric refinement: refine_primitive.h / refine_best_start.h do that when wanted.
// Cost:   O(N) plus a constant number of small eigenproblems (see each fit).
#ifndef PRIMITIVE_EDIT_FIT_QUADRIC_DIRECT_H
#define PRIMITIVE_EDIT_FIT_QUADRIC_DIRECT_H

#include "common/fit/fit_cone_direct.h"
#include "common/fit/fit_cylinder_direct.h"
#include "common/fit/fit_plane_direct.h"
#include "common/fit/fit_sphere_direct.h"

namespace primitive_edit {

FitResult fit_quadric_direct(PrimitiveType type, const Eigen::MatrixX3d& points,
                             const Eigen::VectorXd& weights = {});

} // namespace primitive_edit

#endif
