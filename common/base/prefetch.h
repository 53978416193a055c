// prefetch.h: a hint that memory will be read soon.
//
// Input:  an address (one past the end of an array is fine: the hint never faults).
// Output: none; with GCC and Clang the cache line that holds the address is requested, elsewhere nothing happens.
// Why:    the segmentation's walks over faces (the breadth-first growth of a region, the shares over a region's
//         face list) wait on loads whose addresses are known a few faces ahead: a face's neighbour list, then each
//         neighbour's flags, centroid and normal, in arrays far larger than the caches. Asked for early, those
//         loads overlap (bench/README.md: growth on the 4M-face bracket scan about a tenth faster).
// Cost:   O(1).
#ifndef PRIMITIVE_EDIT_PREFETCH_H
#define PRIMITIVE_EDIT_PREFETCH_H

namespace primitive_edit {

template <class T>
inline void prefetch(const T* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address);
#else
  (void)address;
#endif
}

} // namespace primitive_edit

#endif
