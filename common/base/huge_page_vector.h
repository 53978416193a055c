// huge_page_vector.h: per-face and per-vertex arrays the kernel may back with 2 MiB pages.
//
// Input:  a size n and a value (or none: default-inserted elements), or an existing vector to refill.
// Output: a std::vector<T> of n elements, as std::vector(n, value) or v.assign(n, value) gives, whose buffer
//         was advised to the kernel as huge-page memory (Linux madvise(MADV_HUGEPAGE)) before it was written;
//         from 2 MiB on, its capacity exceeds n by up to 2 MiB (huge_page_capacity).
// Why:    a first call in a process (meshlabserver's every call), or any call on arrays past glibc's 32 MB
//         mmap ceiling, faults its arrays in 4 KiB at a time, about 15 us a fault on a virtual machine.
//         Transparent huge pages in "madvise" mode (a common kernel default) serve a 2 MiB run with one
//         fault: the peer part's segmentation through meshlabserver 1.17 -> 0.94 s, then 0.93 -> 0.87 s with the
//         capacity rounded to whole huge pages and more arrays advised (bench/README.md, Scan segmentation).
//         Elsewhere (THP "always" or "never", other systems) the advice changes nothing; it is never an error.
// Method: reserve a capacity that fills whole 2 MiB pages (huge_page_capacity), advise the whole 2 MiB pages
//         the reserved bytes touch, then fill. The type stays std::vector<T>.
// Cost:   that of the fill, plus one madvise system call per large array.
#ifndef PRIMITIVE_EDIT_HUGE_PAGE_VECTOR_H
#define PRIMITIVE_EDIT_HUGE_PAGE_VECTOR_H

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace primitive_edit {

constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

// Advises the whole 2 MiB pages among the 4 KiB pages that [data, data + bytes) touches: a buffer that starts
// 16 bytes into a huge page (glibc's chunk header before it, as huge_page_capacity arranges) gets that page.
void advise_huge_pages(const void* data, std::size_t bytes);

// The capacity to reserve for n elements of `size` bytes: n under 2 MiB; above, as many elements as fill a
// whole number of 2 MiB pages less glibc's 32 bytes of chunk overhead. glibc then maps exactly whole huge
// pages, which Linux (6.7 on) places on a 2 MiB boundary, so no 4 KiB-paged head or tail is left outside the
// advice (elsewhere this costs under 2 MiB an array).
std::size_t huge_page_capacity(std::size_t n, std::size_t size);

// v can take n elements without reallocating; a buffer it must replace for that is advised. Its contents
// stay only when no new buffer was needed (callers fill it next).
template <class T>
void reserve_on_huge_pages(std::vector<T>& v, std::size_t n)
{
  if (v.capacity() >= n)
    return;
  const std::size_t capacity = huge_page_capacity(n, sizeof(T));
  std::vector<T>().swap(v);
  v.reserve(capacity);
  advise_huge_pages(v.data(), capacity * sizeof(T));
}

// v becomes n copies of value.
template <class T>
void assign_on_huge_pages(std::vector<T>& v, std::size_t n, const T& value)
{
  reserve_on_huge_pages(v, n);
  v.assign(n, value);
}

template <class T>
std::vector<T> huge_page_vector(std::size_t n, const T& value)
{
  std::vector<T> v;
  assign_on_huge_pages(v, n, value);
  return v;
}

// n default-inserted elements (left uninitialised for Eigen's fixed-size types, as std::vector(n) leaves them).
template <class T>
std::vector<T> huge_page_vector(std::size_t n)
{
  std::vector<T> v;
  reserve_on_huge_pages(v, n);
  v.resize(n);
  return v;
}

} // namespace primitive_edit

#endif
