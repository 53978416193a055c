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

// Where a fit starts (fit_primitive.h): each fit_*.h's own starts refined geometrically (the default: the
// most accurate on rough and partial patches, bench/README.md), the paper's type-constrained direct quadric
// fit alone (fit_quadric_direct.h), or that fit refined geometrically. A torus is not a quadric and always
// takes its own starts. fit_method_name is the name the filters' Method parameter and the edit tool show.
enum class FitMethod { Refined, Direct, DirectRefined };
constexpr int kFitMethodCount = 3;

const char* fit_method_name(FitMethod method);

struct FitOptions
{
  bool robust = true;       // Tukey-biweight reweighting of the geometric residual (drops outliers)
  int max_iterations = 50;  // Levenberg-Marquardt iterations per (re)weighting round
  FitMethod method = FitMethod::Refined;
};

} // namespace primitive_edit

#endif
