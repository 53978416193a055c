// Tests of common/base/parallel_for.h: every item is visited once, on any thread count,
// for_each_largest_first deals the items largest first, and "all threads" means the CPUs the caller may use.
#include "common/base/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#if defined(__linux__)
#include <sched.h>
#endif

using primitive_edit::for_each_largest_first;
using primitive_edit::parallel_for;
using primitive_edit::resolve_thread_count;

TEST(ParallelFor, CoversEveryIndexOnce)
{
  for (int threads : {1, 2, 3, 8})
    for (std::size_t count : {std::size_t(0), std::size_t(1), std::size_t(7), std::size_t(1000)}) {
      std::vector<std::atomic<int>> visits(count);
      parallel_for(count, threads, 1, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
          ++visits[i];
      });
      for (std::size_t i = 0; i < count; ++i)
        EXPECT_EQ(visits[i].load(), 1) << "threads " << threads << ", count " << count << ", index " << i;
    }
}

TEST(ForEachLargestFirst, VisitsEveryItemOnceOnWorkersInRange)
{
  const std::vector<std::size_t> sizes = {3, 9, 0, 9, 1, 5, 2, 7, 7, 4};
  for (int workers : {1, 2, 3, 16}) {
    std::vector<std::atomic<int>> visits(sizes.size());
    std::atomic<bool> worker_in_range{true};
    for_each_largest_first(sizes, workers, [&](int worker, std::size_t item) {
      ++visits[item];
      if (worker < 0 || worker >= workers)
        worker_in_range = false;
    });
    for (std::size_t i = 0; i < sizes.size(); ++i)
      EXPECT_EQ(visits[i].load(), 1) << "workers " << workers << ", item " << i;
    EXPECT_TRUE(worker_in_range.load()) << "workers " << workers;
  }
}

TEST(ForEachLargestFirst, OneWorkerTakesTheLargestFirstAndTiesByIndex)
{
  const std::vector<std::size_t> sizes = {3, 9, 0, 9, 1, 5};
  std::vector<std::size_t> taken;
  for_each_largest_first(sizes, 1, [&](int worker, std::size_t item) {
    EXPECT_EQ(worker, 0);
    taken.push_back(item);
  });
  EXPECT_EQ(taken, (std::vector<std::size_t>{1, 3, 5, 0, 4, 2}));
}

TEST(ForEachLargestFirst, NoItemsCallsNothing)
{
  int calls = 0;
  for_each_largest_first({}, 4, [&](int, std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

#if defined(__linux__)
TEST(ResolveThreadCount, AllMeansTheCpusTheCallerMayRunOn)
{
  cpu_set_t saved;
  ASSERT_EQ(sched_getaffinity(0, sizeof saved, &saved), 0);
  int first = 0;
  while (!CPU_ISSET(first, &saved))
    ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);  // as under taskset -c
  const int pinned = resolve_thread_count(0);
  ASSERT_EQ(sched_setaffinity(0, sizeof saved, &saved), 0);
  EXPECT_EQ(pinned, 1);
  EXPECT_EQ(resolve_thread_count(-1), CPU_COUNT(&saved));
  EXPECT_EQ(resolve_thread_count(3), 3);  // a count asked for is kept
}
#endif
