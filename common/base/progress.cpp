#include "common/base/progress.h"

namespace primitive_edit {

bool report_progress(const Progress& progress, int percent, const char* what)
{
  return !progress || progress(percent < 0 ? 0 : (percent > 100 ? 100 : percent), what);
}

Progress progress_range(const Progress& progress, int begin, int end)
{
  if (!progress)
    return {};
  return [progress, begin, end](int percent, const char* what) {
    return progress(begin + (end - begin) * percent / 100, what);
  };
}

} // namespace primitive_edit
