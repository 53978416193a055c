// bench_fit_all: "Primitive: Fit All Segments" with snap on a segmented scan, as the filter runs it:
// the scan's roughness (for the automatic tolerance), gather_segment_samples, fit_segments_auto (automatic type
// and tolerance) and snap_segments with sharp edges.
// Input: a PLY whose per-face quality is the segment id (bench_segment_scan --segmented, or meshlabserver's
// -m fq after a segmentation filter). The fit is run on 1 thread (the baseline) and on all hardware threads,
// each `--runs` times (default 5) on a fresh copy of the mesh; printed: median wall-clock times of each stage
// and the ratio of the two fits.
// Usage: bench_fit_all SEGMENTED.ply [--runs N]
#include "bracket/bracket_mesh.h"

#include "common/mesh/estimate_surface_roughness.h"
#include "common/mesh/face_adjacency.h"
#include "common/pipeline/fit_segments_auto.h"
#include "common/mesh/gather_segment_samples.h"
#include "common/snap/snap_segments.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  using namespace primitive_edit;
  if (argc < 2 || (argc != 2 && !(argc == 4 && std::string(argv[2]) == "--runs"))) {
    std::fprintf(stderr, "usage: bench_fit_all SEGMENTED.ply [--runs N]\n");
    return 2;
  }
  const int runs = argc == 4 ? std::max(1, std::atoi(argv[3])) : 5;
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
  const int hardware = int(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<double> gather, fit_one, fit_all, snap;
  int fitted = 0;
  for (int r = 0; r < runs; ++r) {
    bracket::BMesh m;
    vcg::tri::Append<bracket::BMesh, bracket::BMesh>::MeshCopy(m, original);
    auto t0 = std::chrono::steady_clock::now();
    AutoFitOptions options;
    options.roughness = estimate_surface_roughness(m, build_face_adjacency(m));
    const std::vector<SegmentSamples> samples = gather_segment_samples(m, segment_of_face, count);
    gather.push_back(seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    fit_segments_auto(samples, options, 1);
    fit_one.push_back(seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    const std::vector<AutoFitResult> fits = fit_segments_auto(samples, options, hardware);
    fit_all.push_back(seconds_since(t0));
    std::vector<std::optional<Primitive>> primitives(fits.size());
    fitted = 0;
    for (std::size_t s = 0; s < fits.size(); ++s)
      if (fits[s].ok) {
        primitives[s] = fits[s].best.primitive;
        ++fitted;
      }
    t0 = std::chrono::steady_clock::now();
    snap_segments(m, segment_of_face, primitives);
    snap.push_back(seconds_since(t0));
  }
  std::printf("%s: %zu faces, %d segments, %d fitted; median of %d runs [s]\n", argv[1], original.face.size(), count,
              fitted, runs);
  std::printf("roughness + gather %.3f | fit 1 thread %.3f | fit %d threads %.3f (%.2fx) | snap %.3f | "
              "Fit All with snap (gather + fit on %d threads + snap) %.3f\n",
              median(gather), median(fit_one), hardware, median(fit_all), median(fit_one) / median(fit_all),
              median(snap), hardware, median(gather) + median(fit_all) + median(snap));
  return 0;
}
