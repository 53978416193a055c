#include "common/base/huge_page_vector.h"

namespace primitive_edit {

void advise_huge_pages(const void* data, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kPage = 4096, kHugePage = kHugePageBytes;
  const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(data) & ~(kPage - 1);
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(data) + bytes + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t begin = (first + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t end = last & ~(kHugePage - 1);
  if (begin < end)
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE); // advice: a refusal is harmless
#else
  (void)data;
  (void)bytes;
#endif
}

std::size_t huge_page_capacity(std::size_t n, std::size_t size)
{
  constexpr std::size_t kMallocOverhead = 32;
  if (n * size < kHugePageBytes)
    return n;
  const std::size_t pages = (n * size + kMallocOverhead + kHugePageBytes - 1) / kHugePageBytes;
  return (pages * kHugePageBytes - kMallocOverhead) / size;
}

} // namespace primitive_edit
