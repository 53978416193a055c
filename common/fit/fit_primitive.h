// fit_primitive.h: fit a primitive of a given type (dispatch to fit_plane ... fit_torus).
//
// Input:  the type, points N x 3, normals N x 3 or empty, weights N or empty (= all 1), options.
// Output: the FitResult of that type's fit (see each fit_*.h for the method and conventions); with
//         options.method Direct the paper's direct fit alone (fit_quadric_direct.h), with DirectRefined that
//         fit refined geometrically (refine_primitive.h); a torus always takes fit_torus.
//         minimum_points_for(type) (minimum_points_for.h) is the fewest points each type accepts.
// Cost:   that of the chosen fit, O(N) per LM iteration.
#ifndef PRIMITIVE_EDIT_FIT_PRIMITIVE_H
#define PRIMITIVE_EDIT_FIT_PRIMITIVE_H

#include "common/fit/fit_cone.h"
#include "common/fit/fit_cylinder.h"
#include "common/fit/fit_plane.h"
#include "common/fit/fit_quadric_direct.h"
#include "common/fit/fit_sphere.h"
#include "common/fit/fit_torus.h"
#include "common/fit/minimum_points_for.h"
#include "common/fit/refine_primitive.h"

namespace primitive_edit {

FitResult fit_primitive(PrimitiveType type, const Eigen::MatrixX3d& points, const Eigen::MatrixX3d& normals,
                        const Eigen::VectorXd& weights, const FitOptions& options = {});

} // namespace primitive_edit

#endif
