// bench_fit: time of fit_primitive_auto on segments of 1k, 10k, 100k and 1M points, and of each fit type
// on 100k points (median of 5 runs). Data: noisy (sigma = 0.5% of the size) patches with normals.
#include "common/base/constants.h"
#include "common/fit/fit_primitive_auto.h"
#include "../tests/unit/test_fit_data.h"
#include "median.h"

#include <ctime>
#include <cstdio>
#include <vector>

using namespace primitive_edit;
using namespace test_fit;

namespace {

template <class F>
double median_ms(F&& f, int runs = 5)
{
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    // Process CPU time: the fits are single-threaded and the machine is shared, so wall time would
    // measure the neighbours' load.
    const std::clock_t a = std::clock();
    f();
    t.push_back(1000.0 * double(std::clock() - a) / CLOCKS_PER_SEC);
  }
  return median(t);
}

Sample noisy(const Primitive& p, const Patch& patch, int n)
{
  Sample s = sample_primitive(p, patch, n, 7);
  add_noise(&s, 0.005, 2.0, 8);
  return s;
}

} // namespace

int main()
{
  Patch cyl_patch;
  cyl_patch.sweep = primitive_edit::kPi;
  cyl_patch.extent = 3;
  Patch cone_patch;
  cone_patch.near = 1;
  cone_patch.far = 2;
  Patch cap;
  cap.cap = primitive_edit::kPi / 3;
  const std::vector<std::pair<Primitive, Patch>> shapes = {
      {make_plane({0, 0, 0}, {0.2, 0.1, 1}), Patch()},
      {make_sphere({1, 0, 0}, 1), cap},
      {make_cylinder({0, 0, 0}, {0, 0.3, 1}, 1), cyl_patch},
      {make_cone({0, 0, 0}, {0.1, 0, 1}, 0.4), cone_patch},
      {make_torus({0, 0, 0}, {0, 0, 1}, 2, 0.5), Patch()},
  };

  std::printf("fit_primitive_auto (with normals), median of 5 runs [ms CPU]\n");
  std::printf("%-10s %10s %10s %10s %10s\n", "type", "1k", "10k", "100k", "1M");
  for (const auto& [prim, patch] : shapes) {
    std::printf("%-10s", primitive_type_name(prim.type));
    for (int n : {1000, 10000, 100000, 1000000}) {
      const Sample s = noisy(prim, patch, n);
      AutoFitResult r;
      const double ms = median_ms([&] { r = fit_primitive_auto(s.points, s.normals, Eigen::VectorXd()); });
      std::printf(" %9.2f%s", ms, r.status.ok() && r.best.primitive.type == prim.type ? " " : "!");
    }
    std::printf("\n");
  }
  std::printf("('!' marks a wrong type or a free-form answer)\n\n");

  std::printf("fit_<type> on 100k points, median of 5 runs [ms CPU]\n");
  std::printf("%-10s %12s %12s\n", "type", "normals", "points only");
  for (const auto& [prim, patch] : shapes) {
    const Sample s = noisy(prim, patch, 100000);
    const double with = median_ms([&] { fit_primitive(prim.type, s.points, s.normals, Eigen::VectorXd()); });
    const double without = median_ms([&] { fit_primitive(prim.type, s.points, Eigen::MatrixX3d(), Eigen::VectorXd()); });
    std::printf("%-10s %12.2f %12.2f\n", primitive_type_name(prim.type), with, without);
  }
  return 0;
}
