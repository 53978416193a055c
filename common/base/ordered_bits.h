// ordered_bits.h: a double as an unsigned integer of the same order, for buckets (and radix sorts) over doubles.
//
// Input:  a finite or infinite double (NaN has no place in an order).
// Output: an unsigned 64-bit integer; a < b exactly when ordered_bits(a) < ordered_bits(b), and -0 and +0 map
//         to the same integer, as they compare equal. Its top bits are a monotone bucket of the value: the sign,
//         then the exponent, then the leading mantissa bits (seed_queue.h).
// Method: negative values get all bits flipped, the others the sign bit set.
// Cost:   O(1).
#ifndef PRIMITIVE_EDIT_ORDERED_BITS_H
#define PRIMITIVE_EDIT_ORDERED_BITS_H

#include <cstdint>
#include <cstring>

namespace primitive_edit {

inline std::uint64_t ordered_bits(double key)
{
  key += 0.0; // -0 becomes +0, so that the two tie
  std::uint64_t u;
  std::memcpy(&u, &key, sizeof u);
  return (u >> 63) != 0 ? ~u : u | (std::uint64_t(1) << 63);
}

} // namespace primitive_edit

#endif
