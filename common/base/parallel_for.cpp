#include "common/base/parallel_for.h"

namespace primitive_edit {

int resolve_thread_count(int threads)
{
  return threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

} // namespace primitive_edit
