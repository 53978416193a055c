// Tests of common/base/sort_by_key.h: the same order as std::stable_sort by the key.
#include "common/base/sort_by_key.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace primitive_edit;

std::vector<int> stable_sorted(std::vector<int> items, const std::vector<double>& key)
{
  std::stable_sort(items.begin(), items.end(),
                   [&](int a, int b) { return key[std::size_t(a)] < key[std::size_t(b)]; });
  return items;
}

TEST(SortByKey, OrdersAsAStableSortDoes)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-3, 3);
  std::uniform_int_distribution<int> pick(0, 9);
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> special = {0.0, -0.0, inf, -inf, 1e-310, -1e-310, 1e300, 2.0};
  for (const std::size_t n : {0, 1, 2, 17, 5000}) {
    std::vector<double> key(n);
    for (double& k : key) // a quarter from a few values: ties, signed zeros, infinities, denormals
      k = pick(random) < 3 ? special[std::size_t(pick(random)) % special.size()] : uniform(random);
    std::vector<int> items(n);
    for (std::size_t i = 0; i < n; ++i)
      items[i] = int(n - 1 - i); // ties keep this order, not the index order
    const std::vector<int> expected = stable_sorted(items, key);
    sort_by_key(items, [&](int i) { return key[std::size_t(i)]; });
    EXPECT_EQ(items, expected) << n << " keys";
  }
}

TEST(SortByKey, AllKeysEqualLeaveTheOrder)
{
  std::vector<int> items = {4, 2, 3, 0, 1};
  sort_by_key(items, [](int) { return 0.25; });
  EXPECT_EQ(items, (std::vector<int>{4, 2, 3, 0, 1}));
}

} // namespace
