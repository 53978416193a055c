// Tests of common/base/parallel_for.h: every item is visited once, on any thread count, and
// for_each_largest_first deals the items largest first.
#include "common/base/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

using primitive_edit::for_each_largest_first;
using primitive_edit::parallel_for;

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
