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

TEST(LazyLists, BuiltReadsBuiltListsOnlyAndBuildsNothing)
{
  LazyLists lists(10);
  for (std::size_t i : {3u, 8u, 0u})
    lists.get(i, [&](std::vector<int>& out) {
      const std::vector<int> l = list_of(i);
      out.insert(out.end(), l.begin(), l.end());
    });
  for (std::size_t i = 0; i < 10; ++i) {
    const auto [begin, end] = lists.built(i);
    if (i == 3 || i == 8 || i == 0)
      EXPECT_EQ(std::vector<int>(begin, end), list_of(i)) << "index " << i;
    else
      EXPECT_EQ(begin, end) << "index " << i; // not built: empty, and still not built afterwards
  }
  int builds = 0;
  lists.get(5, [&](std::vector<int>& out) {
    ++builds;
    out.push_back(1);
  });
  EXPECT_EQ(builds, 1);
}

} // namespace
