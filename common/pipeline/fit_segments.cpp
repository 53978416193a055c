#include "common/pipeline/fit_segments.h"

namespace primitive_edit {

std::vector<FitResult> fit_segments(const std::vector<SegmentSamples>& segments,
                                    const std::vector<std::optional<PrimitiveType>>& types,
                                    const AutoFitOptions& options, int threads,
                                    const Progress& progress)
{
  const int count = int(segments.size());
  std::vector<FitResult> out(segments.size());
  std::vector<std::size_t> sizes(segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s)
    sizes[s] = std::size_t(segments[s].points.rows());
  std::atomic<int> done{0};
  const int workers = std::min(resolve_thread_count(threads), count);
  for_each_largest_first(sizes, workers, [&](int worker, std::size_t s) {
    const std::optional<PrimitiveType> type = s < types.size() ? types[s] : std::nullopt;
    out[s] = fit_segment(segments[s], type, options);
    const int finished = ++done;
    if (worker == 0)
      report_progress(progress, 100 * finished / count, "Fitting primitives");
  });
  return out;
}

} // namespace primitive_edit
