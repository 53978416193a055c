// bench_fit_direct: the paper's direct type-constrained quadric fits (fit_quadric_direct.h, issue 14)
// against today's fits, on cylinder and cone patches of 30 to 180 degrees of arc.
//
// Methods: "direct" (the algebraic fit alone, no normals), "direct+refine" (its result refined
// geometrically and robustly by refine_best_start.h), "today+n" / "today" (fit_cylinder / fit_cone with
// their default options, with and without the sampled normals). Data: 500 points per patch; "exact",
// "noise" (Gaussian, sigma = 1% of the radius, normals tilted ~2 degrees), "outliers" (noise plus 10%
// of the points moved by 10-50% of the radius). Figures: medians over 7 seeds of the radius error (% of
// the true radius; cones: radius at the patch's mid height), axis angle error (degrees), apex error
// (cones, % of the apex's distance to the mid height), failures (of 7) and CPU time per fit (us).
#include "common/base/constants.h"
#include "common/fit/fit_primitive.h"
#include "common/fit/fit_quadric_direct.h"
#include "../tests/unit/test_fit_data.h"
#include "median.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

using namespace primitive_edit;
using namespace test_fit;

namespace {

constexpr int kSeeds = 7;
constexpr int kPoints = 500;
constexpr double kMidHeight = 1.5;  // cone patches span apex distances [1, 2]

double cpu_microseconds()
{
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e6 * double(t.tv_sec) + 1e-3 * double(t.tv_nsec);
}

// The median as a table cell; "-" when nothing was measured (cylinder apex, every fit failed).
std::string cell(const std::vector<double>& v)
{
  if (v.empty())
    return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", median(v));
  return text;
}

// Radius of a cylinder, or of a cone at the height of the true cone's mid cross-section.
double radius_at_mid(const Primitive& fitted, const Primitive& truth)
{
  if (fitted.type == PrimitiveType::Cylinder)
    return fitted.radius;
  const Eigen::Vector3d mid = truth.origin + kMidHeight * truth.axis;
  return (mid - fitted.origin).dot(fitted.axis) * std::tan(fitted.half_angle);
}

struct Errors
{
  std::vector<double> radius, axis, apex, time;
  int failures = 0;
};

using Fit = std::function<FitResult(const Sample&)>;

void measure(const Primitive& truth, const Fit& fit, const Sample& s, Errors* e)
{
  const double t0 = cpu_microseconds();
  const FitResult r = fit(s);
  e->time.push_back(cpu_microseconds() - t0);
  if (!r.status.ok() || r.primitive.type != truth.type) {
    ++e->failures;
    return;
  }
  const double true_radius = radius_at_mid(truth, truth);
  e->radius.push_back(100 * std::abs(radius_at_mid(r.primitive, truth) - true_radius) / true_radius);
  e->axis.push_back(degrees_from_radians(std::acos(std::min(1.0, std::abs(r.primitive.axis.dot(truth.axis))))));
  if (truth.type == PrimitiveType::Cone)
    e->apex.push_back(100 * (r.primitive.origin - truth.origin).norm() / kMidHeight);
}

} // namespace

int main()
{
  struct Shape
  {
    std::string name;
    Primitive truth;
  };
  const std::vector<Shape> shapes = {
      {"cylinder", make_cylinder({0.5, -0.3, 0.2}, {0.2, 0.3, 1}, 1)},
      {"cone 10", make_cone({0.2, 0.1, -0.3}, {0.3, -0.2, 1}, radians_from_degrees(10))},
      {"cone 30", make_cone({0.2, 0.1, -0.3}, {0.3, -0.2, 1}, radians_from_degrees(30))},
      {"cone 60", make_cone({0.2, 0.1, -0.3}, {0.3, -0.2, 1}, radians_from_degrees(60))},
  };
  const char* conditions[] = {"exact", "noise", "outliers"};
  std::printf("%-9s %4s %-8s %-14s %9s %9s %9s %5s %9s\n", "shape", "arc", "data", "method", "radius%",
              "axis deg", "apex%", "fail", "us/fit");
  for (const Shape& shape : shapes) {
    const Primitive& truth = shape.truth;
    const double radius = radius_at_mid(truth, truth);
    const Eigen::MatrixX3d none;
    const std::vector<std::pair<std::string, Fit>> methods = {
        {"direct", [&](const Sample& s) { return fit_quadric_direct(truth.type, s.points); }},
        {"direct+refine",
         [&](const Sample& s) {
           const FitResult d = fit_quadric_direct(truth.type, s.points);
           if (!d.status.ok())
             return d;
           return refine_best_start({d.primitive}, s.points, Eigen::VectorXd(),
                                    fit_subsample(s.points, none, Eigen::VectorXd(), 2000), FitOptions());
         }},
        {"today+n", [&](const Sample& s) { return fit_primitive(truth.type, s.points, s.normals, Eigen::VectorXd()); }},
        {"today", [&](const Sample& s) { return fit_primitive(truth.type, s.points, none, Eigen::VectorXd()); }},
    };
    for (double arc : {30.0, 60.0, 90.0, 180.0}) {
      Patch patch;
      patch.sweep = radians_from_degrees(arc);
      patch.extent = 2;
      for (int condition = 0; condition < 3; ++condition) {
        std::vector<Errors> errors(methods.size());
        for (int seed = 0; seed < kSeeds; ++seed) {
          Sample s = sample_primitive(truth, patch, kPoints, 100 + seed);
          if (condition >= 1)
            add_noise(&s, 0.01 * radius, 2.0, 200 + seed);
          if (condition == 2)
            add_outliers(&s, 0.1, 0.1 * radius, 0.5 * radius, 300 + seed);
          for (size_t m = 0; m < methods.size(); ++m)
            measure(truth, methods[m].second, s, &errors[m]);
        }
        for (size_t m = 0; m < methods.size(); ++m) {
          const Errors& e = errors[m];
          std::printf("%-9s %4.0f %-8s %-14s %9s %9s %9s %5d %9.0f\n", shape.name.c_str(), arc,
                      conditions[condition], methods[m].first.c_str(), cell(e.radius).c_str(), cell(e.axis).c_str(),
                      cell(e.apex).c_str(), e.failures, median(e.time));
        }
      }
    }
  }
  return 0;
}
