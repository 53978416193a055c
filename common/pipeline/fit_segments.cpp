#include "common/pipeline/fit_segments.h"

namespace primitive_edit {

std::vector<FitResult> fit_segments(const std::vector<SegmentSamples>& segments,
                                    const std::vector<std::optional<PrimitiveType>>& types,
                                    const AutoFitOptions& options, int threads,
                                    const Progress& progress)
{
  const int count = int(segments.size());
  std::vector<FitResult> out(segments.size());
  std::vector<int> order(segments.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return segments[size_t(a)].points.rows() > segments[size_t(b)].points.rows();
  });

  std::atomic<int> next{0}, done{0};
  auto work = [&](bool report) {
    for (int i = next++; i < count; i = next++) {
      const int s = order[size_t(i)];
      const std::optional<PrimitiveType> type = size_t(s) < types.size() ? types[size_t(s)] : std::nullopt;
      out[size_t(s)] = fit_segment(segments[size_t(s)], type, options);
      const int finished = ++done;
      if (report)
        report_progress(progress, 100 * finished / count, "Fitting primitives");
    }
  };

  threads = std::max(1, std::min(resolve_thread_count(threads), count));
  std::vector<std::thread> helpers;
  for (int t = 1; t < threads; ++t)
    helpers.emplace_back(work, false);
  work(true);
  for (std::thread& h : helpers)
    h.join();
  return out;
}

} // namespace primitive_edit
