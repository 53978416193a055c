#include "common/base/parallel_for.h"

#if defined(__linux__)
#include <sched.h>
#endif

namespace primitive_edit {

int resolve_thread_count(int threads)
{
  if (threads > 0)
    return threads;
#if defined(__linux__)
  // hardware_concurrency counts the machine's CPUs; a process pinned to fewer (taskset, a container's cpuset)
  // would run that many threads on them, each a slice of a CPU.
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0 && CPU_COUNT(&allowed) > 0)
    return CPU_COUNT(&allowed);
#endif
  return int(std::max(1u, std::thread::hardware_concurrency()));
}

} // namespace primitive_edit
