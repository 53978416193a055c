// Tests of common/base/huge_page_vector.h: the vectors std::vector gives, and on Linux with transparent huge
// pages the advice on their buffers (the "hg" flag of the mapping in /proc/self/smaps).
#include "common/base/huge_page_vector.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace primitive_edit;

constexpr std::size_t kFourMiBOfDoubles = (std::size_t(4) << 20) / sizeof(double);

TEST(HugePageVector, HoldsWhatStdVectorHolds)
{
  for (const std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(1000), kFourMiBOfDoubles - 1,
                              kFourMiBOfDoubles, 3 * kFourMiBOfDoubles + 5}) {
    EXPECT_EQ(huge_page_vector(n, 2.5), std::vector<double>(n, 2.5)) << n;
    EXPECT_EQ(huge_page_vector<int>(n), std::vector<int>(n)) << n;
    std::vector<double> v = {1.0, 2.0};
    assign_on_huge_pages(v, n, -1.0);
    EXPECT_EQ(v, std::vector<double>(n, -1.0)) << n;
  }
}

TEST(HugePageVector, RefillKeepsABufferLargeEnough)
{
  std::vector<int> v = huge_page_vector(3 * kFourMiBOfDoubles, 7);
  const int* buffer = v.data();
  assign_on_huge_pages(v, kFourMiBOfDoubles, 1);
  EXPECT_EQ(v.data(), buffer);
  EXPECT_EQ(v, std::vector<int>(kFourMiBOfDoubles, 1));
}

TEST(HugePageVector, ReserveKeepsContentsOnlyWhenTheBufferSuffices)
{
  std::vector<int> v = {4, 5, 6};
  v.reserve(10);
  reserve_on_huge_pages(v, 8);
  EXPECT_EQ(v, std::vector<int>({4, 5, 6}));
  reserve_on_huge_pages(v, 2 * kFourMiBOfDoubles);
  EXPECT_TRUE(v.empty());
  EXPECT_GE(v.capacity(), 2 * kFourMiBOfDoubles);
}

TEST(HugePageVector, CapacityFillsWholeHugePagesLessMallocOverhead)
{
  constexpr std::size_t kHuge = kHugePageBytes, kOverhead = 32;
  for (const std::size_t size : {std::size_t(1), std::size_t(4), std::size_t(8), std::size_t(24)})
    for (const std::size_t n : {std::size_t(0), std::size_t(1000), kHuge / size - 1, kHuge / size, std::size_t(1000000),
                                3 * kHuge / size + 7}) {
      const std::size_t capacity = huge_page_capacity(n, size);
      if (n * size < kHuge) {
        EXPECT_EQ(capacity, n) << n << " x " << size;
        continue;
      }
      const std::size_t whole_pages = (n * size + kOverhead + kHuge - 1) / kHuge * kHuge;
      EXPECT_GE(capacity, n) << n << " x " << size;
      EXPECT_LE(capacity * size + kOverhead, whole_pages) << n << " x " << size;
      EXPECT_GT(capacity * size + kOverhead + size, whole_pages) << n << " x " << size;
    }
}

// The VmFlags of the mapping that holds address, or "" when /proc/self/smaps is not readable.
std::string mapping_flags(const void* address)
{
  std::ifstream smaps("/proc/self/smaps");
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-')
      inside = begin <= a && a < end;
    else if (inside && line.rfind("VmFlags:", 0) == 0)
      return line;
  }
  return "";
}

TEST(HugePageVector, AdvisesTheKernelOnLinux)
{
  const int on_the_stack = 0;
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled") || mapping_flags(&on_the_stack).empty())
    GTEST_SKIP() << "no transparent huge pages or no /proc/self/smaps here";
  const std::vector<double> large = huge_page_vector(3 * kFourMiBOfDoubles, 1.0);
  // The middle of a 12 MiB buffer lies in its 2 MiB-aligned part.
  EXPECT_NE(mapping_flags(&large[large.size() / 2]).find(" hg"), std::string::npos);
}

} // namespace
