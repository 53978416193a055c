// parallel_for.h: a loop over [0, count) split into contiguous ranges, one per thread.
//
// Input:  count, the threads to use (<= 0: std::thread::hardware_concurrency()), the fewest items worth a
//         thread of their own (grain), and body(begin, end), called once per range.
// Output: none; the ranges are disjoint and cover [0, count), the calling thread takes the first. A body that
//         writes only what belongs to its own indices gives the same result for every thread count.
// Method: thread t takes [t * count / T, (t + 1) * count / T) with T = min(threads, count / grain); no pool,
//         so a call costs a few tens of microseconds of thread start per extra thread.
// Cost:   the body's cost divided by T, plus the thread starts.
#ifndef PRIMITIVE_EDIT_PARALLEL_FOR_H
#define PRIMITIVE_EDIT_PARALLEL_FOR_H

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace primitive_edit {

// The threads a "threads" parameter asks for: itself when positive, else every hardware thread.
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

} // namespace primitive_edit

#endif
