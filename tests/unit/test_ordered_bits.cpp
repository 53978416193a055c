// Tests of common/base/ordered_bits.h: the integers are in the doubles' order, and equal doubles give one integer.
#include "common/base/ordered_bits.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

using primitive_edit::ordered_bits;

TEST(OrderedBits, KeepTheOrderOfDoubles)
{
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> values = {0.0, -0.0, inf, -inf, 1e-310, -1e-310, 1e300, -1e300, 2.0, -2.0, 0.5, 1.0};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-3, 3);
  for (int i = 0; i < 200; ++i)
    values.push_back(uniform(random));
  for (const double a : values)
    for (const double b : values) {
      EXPECT_EQ(a < b, ordered_bits(a) < ordered_bits(b)) << a << " " << b;
      EXPECT_EQ(a == b, ordered_bits(a) == ordered_bits(b)) << a << " " << b;
    }
}
