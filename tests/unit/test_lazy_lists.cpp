// Tests of common/base/lazy_lists.h: each list is built once, on its first request, and read back whole
// however the pool grows around it.
#include "common/base/lazy_lists.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <random>
#include <vector>

namespace {

using namespace primitive_edit;

std::vector<int> list_of(std::size_t index)
{
  std::vector<int> out;
  for (std::size_t k = 0; k < index % 7; ++k)  // lengths 0..6, the empty list too
    out.push_back(int(index * 10 + k));
  return out;
}

TEST(LazyLists, BuildsEachListOnceAndKeepsIt)
{
  const std::size_t count = 500;
  LazyLists lists(count);
  std::vector<int> builds(count, 0);
  std::mt19937 random(3);
  std::uniform_int_distribution<std::size_t> pick(0, count - 1);
  for (int request = 0; request < 20000; ++request) {
    const std::size_t i = pick(random);
    const auto [begin, end] = lists.get(i, [&](std::vector<int>& out) {
      ++builds[i];
      const std::vector<int> l = list_of(i);
      out.insert(out.end(), l.begin(), l.end());
    });
    ASSERT_EQ(std::vector<int>(begin, end), list_of(i)) << "index " << i;
  }
  for (std::size_t i = 0; i < count; ++i)
    EXPECT_LE(builds[i], 1) << "index " << i;
}

} // namespace
