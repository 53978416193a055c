// fit_result.h: the result and options of every primitive fit (fit_plane ... fit_torus, fit_primitive).
//
// A fit reports the primitive (see primitive.h for the parameter conventions), the RMS and maximum
// orthogonal distance of the points it kept (weight > 0 after the robust step, input weights used in
// the RMS) and how many they are. A failed status means no primitive could be fitted; its error says why.
// Cost: none (plain data).
#ifndef PRIMITIVE_EDIT_FIT_RESULT_H
#define PRIMITIVE_EDIT_FIT_RESULT_H

#include "common/base/primitive.h"
#include "common/base/status.h"

namespace primitive_edit {

struct FitResult
{
  Status status;         // failure: why no primitive could be fitted; primitive then unspecified
  Primitive primitive;
  double rms = 0, max_residual = 0;  // orthogonal distances of inlier points (weights > 0 after robust step)
  int point_count = 0;   // points used
};

struct FitOptions
{
  bool robust = true;       // Tukey-biweight reweighting of the geometric residual (drops outliers)
  int max_iterations = 50;  // Levenberg-Marquardt iterations per (re)weighting round
};

} // namespace primitive_edit

#endif
