// bench_segment_scan: segment_by_primitive_growing (default parameters unless overridden) on a scan PLY, then the whole
// reverse-engineering pipeline: fit every segment with fit_primitive_auto (as "Primitive: Fit All
// Segments" does, automatic tolerance) and snap them (snap_segments).
// Prints the median wall-clock time of `--runs` segmentations (adjacency included), the fit and snap times,
// and writes:
//   --segmented OUT.ply  the scan with face quality = segment id (for bench/score_segmentation.py),
//   --fits OUT.json      the fitted primitive of each segment (score_segmentation.py's FIT_EXPORT.json),
//   --snapped OUT.ply    the scan after snapping (for bench/bracket/measure_scan).
// Usage: bench_segment_scan SCAN.ply [--runs N] [--tolerance MM] [--angle DEG] [--smoothing N] [--segmented OUT.ply] [--fits OUT.json] [--snapped OUT.ply]
#include "bracket/bracket_mesh.h"

#include "common/face_adjacency.h"
#include "common/fit_primitive_auto.h"
#include "common/gather_segment_samples.h"
#include "common/segment_by_primitive_growing.h"
#include "common/snap_segments.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void write_fits(const std::string& path, const std::vector<primitive_edit::AutoFitResult>& fits)
{
  std::ofstream out(path);
  out << "{\"segments\": [\n";
  bool first = true;
  for (std::size_t s = 0; s < fits.size(); ++s) {
    if (!fits[s].ok)
      continue;
    const primitive_edit::Primitive& p = fits[s].best.primitive;
    out << (first ? "" : ",\n") << "  {\"id\": " << s << ", \"type\": \"" << primitive_edit::primitive_type_name(p.type)
        << "\", \"rms\": " << fits[s].best.rms << ", \"parameters\": {\"radius\": " << p.radius << "}}";
    first = false;
  }
  out << "\n]}\n";
}

} // namespace

int main(int argc, char** argv)
{
  std::string scan_path, segmented_path, fits_path, snapped_path;
  int runs = 3;
  primitive_edit::SegmentByPrimitiveGrowingParams params;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--runs" && has_value)
      runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--tolerance" && has_value)
      params.tolerance = std::atof(argv[++i]);
    else if (a == "--angle" && has_value)
      params.normal_angle_deg = std::atof(argv[++i]);
    else if (a == "--smoothing" && has_value)
      params.smoothing_iterations = std::atoi(argv[++i]);
    else if (a == "--segmented" && has_value)
      segmented_path = argv[++i];
    else if (a == "--fits" && has_value)
      fits_path = argv[++i];
    else if (a == "--snapped" && has_value)
      snapped_path = argv[++i];
    else if (a.rfind("--", 0) != 0 && scan_path.empty())
      scan_path = a;
    else {
      scan_path.clear();
      break;
    }
  }
  if (scan_path.empty()) {
    std::fprintf(stderr, "usage: bench_segment_scan SCAN.ply [--runs N] [--tolerance MM] [--angle DEG] [--smoothing N] [--segmented OUT.ply] [--fits OUT.json] "
                         "[--snapped OUT.ply]\n");
    return 2;
  }
  bracket::BMesh m;
  std::string message;
  if (!bracket::load_ply(m, scan_path, false, &message)) {
    std::fprintf(stderr, "bench_segment_scan: %s\n", message.c_str());
    return 1;
  }

  using namespace primitive_edit;
  std::vector<double> times;
  std::vector<int> segment_of_face;
  SegmentByPrimitiveGrowingReport report;
  int K = 0;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    K = segment_by_primitive_growing(m, params, segment_of_face, &report);
    times.push_back(seconds_since(t0));
  }
  std::sort(times.begin(), times.end());
  int typed = 0;
  for (const auto& p : report.primitive_of_segment)
    typed += p.has_value() ? 1 : 0;
  std::printf("%s: %zu faces, %d segments (%d with a grown primitive, %d regions grown), tolerance %.4g, "
              "roughness %.4g\n",
              scan_path.c_str(), m.face.size(), K, typed, report.grown_regions, report.tolerance, report.roughness);
  std::printf("segmentation: median %.3f s of %d runs (min %.3f, max %.3f), %.0f ns/face\n", times[times.size() / 2],
              runs, times.front(), times.back(), 1e9 * times[times.size() / 2] / double(m.face.size()));

  if (!segmented_path.empty()) {
    for (std::size_t f = 0; f < m.face.size(); ++f)
      m.face[f].Q() = segment_of_face[f];
    if (!bracket::save_ply(m, segmented_path, true))
      std::fprintf(stderr, "bench_segment_scan: cannot write %s\n", segmented_path.c_str());
  }

  auto t0 = std::chrono::steady_clock::now();
  const std::vector<SegmentSamples> samples = gather_segment_samples(m, segment_of_face, K);
  std::vector<AutoFitResult> fits(samples.size());
  std::vector<std::optional<Primitive>> primitives(samples.size());
  int fitted = 0;
  for (std::size_t s = 0; s < samples.size(); ++s) {
    fits[s] = fit_primitive_auto(samples[s].points, samples[s].normals, samples[s].weights);
    if (fits[s].ok) {
      primitives[s] = fits[s].best.primitive;
      ++fitted;
    }
  }
  const double fit_time = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const SnapReport snap = snap_segments(m, segment_of_face, primitives);
  const double snap_time = seconds_since(t0);
  std::printf("fit all segments: %.3f s, %d of %d fitted; snap: %.3f s, %d vertices moved (%d edge, %d corner, "
              "%d reverted)\n",
              fit_time, fitted, K, snap_time, snap.moved_vertices, snap.edge_vertices, snap.corner_vertices,
              snap.reverted_vertices);
  if (!fits_path.empty())
    write_fits(fits_path, fits);
  if (!snapped_path.empty() && !bracket::save_ply(m, snapped_path, false))
    std::fprintf(stderr, "bench_segment_scan: cannot write %s\n", snapped_path.c_str());
  return 0;
}
