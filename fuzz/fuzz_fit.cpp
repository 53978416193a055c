// fuzz_fit.cpp: libFuzzer target over the fits of common/fit/ on small point sets, so that a long run covers
// them at thousands of inputs a second (fuzz_common runs them inside the whole pipeline, a few a second).
//
// The bytes are decoded (fuzz_input.h) into up to 100 points of a patch of a plane, sphere, cylinder, cone or
// torus (or raw coordinates) with noise and special values, optional normals and weights, fit options and a
// start primitive. Entry points: fit_primitive of a decoded type with each method, fit_quadric_direct,
// fit_primitive_auto, refine_primitive from the decoded start, fit_segment, describe_primitive of the start, and
// reduce_degenerate_cone of the refined start.
// Invariants: a fit that reports success gives a valid primitive of the type asked with finite residuals, the
// same input gives the same result again (no state between calls), and what is shown of a value is itself or 0.
#include "common/base/describe_primitive.h"
#include "common/fit/fit_primitive.h"
#include "common/fit/fit_primitive_auto.h"
#include "common/fit/fit_quadric_direct.h"
#include "common/fit/reduce_degenerate_cone.h"
#include "common/fit/refine_primitive.h"
#include "common/pipeline/fit_segment.h"
#include "fuzz/fuzz_input.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

using namespace primitive_edit;
using namespace fuzz;

namespace {

constexpr int kMaxPoints = 100;

Eigen::MatrixX3d decode_normals(Decoder& in, Eigen::Index n)
{
  if (in.bit())
    return {};
  Eigen::MatrixX3d normals(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    normals.row(i) = in.u8() % 16 == 0 ? Eigen::RowVector3d(in.special(1), in.special(1), in.special(1))
                                       : unit_vector(in).transpose();
  return normals;
}

void check_same(const FitResult& a, const FitResult& b)
{
  FUZZ_CHECK(a.status.ok() == b.status.ok());
  if (a.status.ok())
    FUZZ_CHECK(a.primitive.type == b.primitive.type && a.primitive.origin == b.primitive.origin &&
               a.primitive.axis == b.primitive.axis && a.rms == b.rms);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Decoder in(data, size);
  Primitive surface;
  const Eigen::MatrixX3d points = shape_points(in, kMaxPoints, surface);
  const Eigen::MatrixX3d normals = decode_normals(in, points.rows());
  const Eigen::VectorXd weights = decode_weights(in, points.rows());
  FitOptions options;
  options.robust = in.bit();
  options.max_iterations = int(in.u8() % 24) - 2;
  options.method = static_cast<FitMethod>(in.u8() % kFitMethodCount);
  const PrimitiveType type = in.bit() ? surface.type : static_cast<PrimitiveType>(in.u8() % kPrimitiveTypeCount);

  const FitResult fit = fit_primitive(type, points, normals, weights, options);
  check_fit(fit);
  FUZZ_CHECK(!fit.status.ok() || fit.primitive.type == type);
  check_same(fit, fit_primitive(type, points, normals, weights, options));

  const FitResult direct = fit_quadric_direct(type, points, weights);
  check_fit(direct);
  FUZZ_CHECK(!direct.status.ok() || (direct.primitive.type == type && type != PrimitiveType::Torus));

  // Refinement from a decoded start (the edit tool's edited parameters), valid or not.
  const Primitive start = in.bit() ? fuzz_primitive(in) : surface;
  const FitResult refined = refine_primitive(start, points, weights, options, int(in.u8() % 8));
  check_fit(refined);
  FUZZ_CHECK(!refined.status.ok() || refined.primitive.type == start.type);

  // What the log and the edit tool's panel show of a primitive, valid or not: each value itself or 0.
  FUZZ_CHECK(!describe_primitive(start).empty());
  for (int i = 0; i < 3; ++i)
    for (const auto& [x, scale] : {std::pair{start.origin[i], primitive_size(start)}, std::pair{start.axis[i], 1.0}}) {
      const double y = shown_value(x, scale);
      FUZZ_CHECK(y == x || y == 0 || std::isnan(x));
    }

  // The automatic type (every type is tried: the slowest entry point, so one input in four).
  AutoFitOptions automatic;
  automatic.fit = options;
  automatic.tolerance = in.special(0.1);
  automatic.roughness = in.special(0.05);
  const unsigned char pick = in.u8();
  if (pick % 4 == 0) {
    const AutoFitResult r = fit_primitive_auto(points, normals, weights, automatic);
    for (const FitResult& c : r.candidates)
      check_fit(c);
    FUZZ_CHECK(!r.status.ok() || primitive_is_valid(r.best.primitive));
    if (pick % 8 == 0) { // the candidate types side by side: the same fits
      AutoFitOptions two = automatic;
      two.threads = 2;
      const AutoFitResult r2 = fit_primitive_auto(points, normals, weights, two);
      FUZZ_CHECK(r2.status.ok() == r.status.ok() && r2.candidates.size() == r.candidates.size());
      for (std::size_t t = 0; t < r.candidates.size(); ++t)
        check_same(r.candidates[t], r2.candidates[t]);
      check_same(r.best, r2.best);
    }
  }

  // The filters' fit of a segment, given a type (the automatic one is the call above).
  SegmentSamples samples;
  samples.points = points;
  samples.normals = normals.rows() == points.rows() ? normals : Eigen::MatrixX3d::Zero(points.rows(), 3);
  samples.weights = weights.size() == points.rows() ? weights : Eigen::VectorXd::Ones(points.rows());
  const FitResult segment = fit_segment(samples, type, automatic);
  check_fit(segment);
  FUZZ_CHECK(!segment.status.ok() || (segment.primitive.type == type && primitive_is_valid(segment.primitive)));

  // A refined cone that no longer bends within a tolerance becomes its plane, one that no longer tapers its
  // cylinder (the segmentation's refits); any other fit stays as it is.
  const double tolerance = in.special(0.1);
  const FitResult reduced = reduce_degenerate_cone(refined, points, weights, tolerance, options);
  check_fit(reduced);
  const bool cone = refined.status.ok() && refined.primitive.type == PrimitiveType::Cone;
  const bool reduced_to = cone && reduced.primitive.type != PrimitiveType::Cone;
  FUZZ_CHECK(reduced_to ? reduced.status.ok() && primitive_is_valid(reduced.primitive)
                        : reduced.primitive.type == refined.primitive.type);
  if (reduced_to && reduced.primitive.type == PrimitiveType::Plane)
    FUZZ_CHECK(cone_is_plane_within(refined.primitive, points, weights, tolerance));
  else if (reduced_to)
    FUZZ_CHECK(reduced.primitive.type == PrimitiveType::Cylinder &&
               cone_is_cylinder_within(refined.primitive, points, weights, tolerance));
  return 0;
}
