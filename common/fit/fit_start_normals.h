// fit_start_normals.h: the normals the fits use to guess their start, given or estimated.
//
// Input:  a fit subsample (fit_subsample.h).
// Output: its normals when it has some, otherwise the normals of a Taubin quadric fitted to its
//         points (estimate_normals_from_quadric.h; empty when that is degenerate). Normals only seed
//         the start: every fit also tries starts that need none.
// Cost:   O(n) for n sample points.
#ifndef PRIMITIVE_EDIT_FIT_START_NORMALS_H
#define PRIMITIVE_EDIT_FIT_START_NORMALS_H

#include "common/fit/estimate_normals_from_quadric.h"
#include "common/fit/fit_subsample.h"

namespace primitive_edit {

Eigen::MatrixX3d fit_start_normals(const FitSample& sample);

} // namespace primitive_edit

#endif
