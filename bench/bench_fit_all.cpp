// bench_fit_all: "Primitive: Fit All Segments" with snap on a segmented scan: fit_all_segments, the core call
// the filter makes (the scan's roughness for the automatic tolerance, gather_segment_samples, fit_segments with
// the automatic type, snap_segments with sharp edges).
// Input: a PLY whose per-face quality is the segment id (bench_segment_scan --segmented, or meshlabserver's
// -m fq after a segmentation filter). The fit is run on 1 thread (the baseline) and on every CPU it may use,
// each `--runs` times (default 5) on a fresh copy of the mesh; printed: median wall-clock times of each stage
// and the ratio of the two fits.
// Usage: bench_fit_all SEGMENTED.ply [--runs N]
#include "bracket/bracket_mesh.h"

#include "common/base/parallel_for.h"
#include "common/pipeline/fit_all_segments.h"
#include "median.h"
#include "read_number.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

} // namespace

int main(int argc, char** argv)
{
  using namespace primitive_edit;
  if (argc < 2 || (argc != 2 && !(argc == 4 && std::string(argv[2]) == "--runs"))) {
    std::fprintf(stderr, "usage: bench_fit_all SEGMENTED.ply [--runs N]\n");
    return 2;
  }
  int runs = 5;
  if (argc == 4 && !read_number("--runs", argv[3], 1, kMaxRuns, runs))
    return 2;
  bracket::BMesh original;
  std::string message;
  if (!bracket::load_ply(original, argv[1], true, &message)) {
    std::fprintf(stderr, "bench_fit_all: %s\n", message.c_str());
    return 1;
  }
  std::vector<int> segment_of_face(original.face.size());
  int count = 0;
  for (std::size_t f = 0; f < original.face.size(); ++f) {
    segment_of_face[f] = int(original.face[f].Q());
    count = std::max(count, segment_of_face[f] + 1);
  }
  const int hardware = primitive_edit::resolve_thread_count(0);
  std::vector<double> fit_one, fit_all, snap;
  int fitted = 0;
  for (int r = 0; r < runs; ++r) {
    bracket::BMesh m;
    vcg::tri::Append<bracket::BMesh, bracket::BMesh>::MeshCopy(m, original);
    FitAllSegmentsOptions options;
    options.threads = 1;
    fit_one.push_back(fit_all_segments(m, segment_of_face, options).fit_seconds);
    options.threads = hardware;
    options.snap = true;
    const FitAllSegmentsResult result = fit_all_segments(m, segment_of_face, options);
    if (!result.status) {
      std::fprintf(stderr, "bench_fit_all: %s\n", result.status.error.c_str());
      return 1;
    }
    fit_all.push_back(result.fit_seconds);
    snap.push_back(result.snap_seconds);
    fitted = result.fitted;
  }
  std::printf("%s: %zu faces, %d segments, %d fitted; median of %d runs [s]\n", argv[1], original.face.size(), count,
              fitted, runs);
  std::printf("roughness + gather + fit: 1 thread %.3f | %d threads %.3f (%.2fx) | snap %.3f | "
              "Fit All with snap on %d threads %.3f\n",
              median(fit_one), hardware, median(fit_all), median(fit_one) / median(fit_all), median(snap), hardware,
              median(fit_all) + median(snap));
  return 0;
}
