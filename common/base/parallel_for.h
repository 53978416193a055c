// parallel_for.h: loops over items on several threads: parallel_for splits [0, count) into contiguous ranges,
// one per thread, for items of equal cost; for_each_largest_first deals items of unequal cost one at a time.
//
// Input:  parallel_for: count, the threads to use (<= 0: every CPU the calling thread may run on, its affinity
//         on Linux, else std::thread::hardware_concurrency()), the fewest items worth a thread of their own
//         (grain), and body(begin, end), called once per range.
//         for_each_largest_first: each item's size (its cost), the workers (>= 1, the caller's count) and
//         body(worker, item), worker in [0, workers), called once per item.
// Output: none. parallel_for's ranges are disjoint and cover [0, count), the calling thread takes the first.
//         for_each_largest_first's worker 0 is the calling thread (the one that may report progress). A body
//         that writes only what belongs to its own items gives the same result for every thread count.
// Method: parallel_for: thread t takes [t * count / T, (t + 1) * count / T) with T = min(threads, count /
//         grain). for_each_largest_first: the items sorted by size, largest first (ties by index), and each
//         worker takes the next one not yet taken (an atomic counter), so the longest start first and the
//         workers finish together. No pool: a call costs a few tens of microseconds per extra thread.
// Cost:   the body's cost divided by the threads, plus the thread starts (and a sort of the sizes).
#ifndef PRIMITIVE_EDIT_PARALLEL_FOR_H
#define PRIMITIVE_EDIT_PARALLEL_FOR_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <numeric>
#include <thread>
#include <vector>

namespace primitive_edit {

// The threads a "threads" parameter asks for: itself when positive, else every CPU the calling thread may run
// on (taskset and a container's cpuset count; a CPU quota does not).
int resolve_thread_count(int threads);

// The grain of a pass that does a few arithmetic operations per face of a mesh: below this many faces a second
// thread costs more than it saves.
constexpr std::size_t kFacesPerThread = 20000;

template <class Body>
void parallel_for(std::size_t count, int threads, std::size_t grain, const Body& body)
{
  const std::size_t most = std::max<std::size_t>(1, count / std::max<std::size_t>(1, grain));
  const std::size_t t_count = std::min<std::size_t>(std::size_t(resolve_thread_count(threads)), most);
  if (t_count <= 1) {
    body(std::size_t(0), count);
    return;
  }
  std::vector<std::thread> helpers;
  for (std::size_t t = 1; t < t_count; ++t)
    helpers.emplace_back([&body, t, t_count, count] { body(t * count / t_count, (t + 1) * count / t_count); });
  body(std::size_t(0), count / t_count);
  for (std::thread& h : helpers)
    h.join();
}

template <class Body>
void for_each_largest_first(const std::vector<std::size_t>& sizes, int workers, const Body& body)
{
  std::vector<std::size_t> order(sizes.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sizes[a] > sizes[b]; });
  std::atomic<std::size_t> next{0};
  auto work = [&](int worker) {
    for (std::size_t i = next++; i < order.size(); i = next++)
      body(worker, order[i]);
  };
  const std::size_t count = std::max<std::size_t>(1, std::min(std::size_t(std::max(workers, 1)), sizes.size()));
  std::vector<std::thread> helpers;
  for (int w = 1; w < int(count); ++w)
    helpers.emplace_back(work, w);
  work(0);
  for (std::thread& h : helpers)
    h.join();
}

} // namespace primitive_edit

#endif
