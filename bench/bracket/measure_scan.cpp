// measure_scan: the paper's accuracy measure (section 3) of a mesh against a reference (CAD) mesh:
// N samples uniform by area on the mesh, the shortest distance of each to the reference, the share
// within the tolerance (the paper's "accuracy", 0.42 mm after KS B 0250) and the mean distance.
// The paper's input scan: 54.3% within 0.42 mm, mean 0.43 mm; its edited mesh: 81.4%, mean 0.21 mm.
//
// Usage: measure_scan MESH.ply REFERENCE.ply [--samples N] [--tolerance MM] [--seed N]
#include "bracket_mesh.h"
#include "bench/read_number.h"

#include "common/measure/measure_accuracy.h"
#include "common/mesh/sample_surface_uniform.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

int main(int argc, char** argv)
{
  std::string mesh_path, reference_path;
  long samples = 1000000;
  double tolerance = 0.42;
  long long seed = 1;
  bool ok = true;
  for (int i = 1; i < argc && ok; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--samples" && has_value)
      ok = read_number("--samples", argv[++i], samples);
    else if (a == "--tolerance" && has_value)
      ok = read_number("--tolerance", argv[++i], tolerance);
    else if (a == "--seed" && has_value)
      ok = read_number("--seed", argv[++i], 0LL, std::numeric_limits<long long>::max(), seed);
    else if (a.rfind("--", 0) != 0 && mesh_path.empty())
      mesh_path = a;
    else if (a.rfind("--", 0) != 0 && reference_path.empty())
      reference_path = a;
    else
      ok = false;
  }
  if (!ok || mesh_path.empty() || reference_path.empty() || samples < 1 || !(tolerance > 0) || !std::isfinite(tolerance)) {
    std::fprintf(stderr, "usage: measure_scan MESH.ply REFERENCE.ply [--samples N (1000000)] [--tolerance MM (0.42)] "
                         "[--seed N (1)]\n");
    return 2;
  }

  bracket::BMesh mesh, reference;
  std::string message;
  if (!bracket::load_ply(mesh, mesh_path, false, &message) || !bracket::load_ply(reference, reference_path, false, &message)) {
    std::fprintf(stderr, "measure_scan: %s\n", message.c_str());
    return 1;
  }
  const auto t0 = std::chrono::steady_clock::now();
  Eigen::MatrixX3d points;
  if (const primitive_edit::Status s = primitive_edit::sample_surface_uniform(mesh, samples, std::uint64_t(seed), &points); !s) {
    std::fprintf(stderr, "measure_scan: %s: %s\n", mesh_path.c_str(), s.error.c_str());
    return 1;
  }
  const primitive_edit::AccuracyReport r = primitive_edit::measure_accuracy(points, reference, tolerance);
  if (!r.status) {
    std::fprintf(stderr, "measure_scan: %s\n", r.status.error.c_str());
    return 1;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("measure_scan: %s: %d faces, %ld samples: %.1f%% within %.3g mm, mean %.3f mm, rms %.3f mm, "
              "max %.3f mm (%.1f s)\n",
              mesh_path.c_str(), mesh.fn, samples, 100.0 * r.within_tolerance_share, tolerance, r.mean, r.rms, r.max, secs);
  std::printf("measure_scan: histogram (bins of %.3g mm, last >= %.3g mm):", r.histogram_bin_width, 2 * tolerance);
  for (Eigen::Index count : r.histogram)
    std::printf(" %.1f%%", 100.0 * double(count) / double(r.sample_count));
  std::printf("\n");
  return 0;
}
