// known_scale.h: whether a scan's roughness (or noise level) is known.
//
// Input:  a roughness as a caller or a mesh attribute gives it.
// Output: true when it is a finite positive number. Zero, a negative number, NaN and infinity all mean
//         "unknown": the caller estimates it or goes without. An infinite one taken as known would make a
//         tolerance infinite and every candidate eligible.
// Cost:   O(1).
#ifndef PRIMITIVE_EDIT_KNOWN_SCALE_H
#define PRIMITIVE_EDIT_KNOWN_SCALE_H

#include <cmath>

namespace primitive_edit {

inline bool is_known_scale(double roughness) { return roughness > 0 && std::isfinite(roughness); }

} // namespace primitive_edit

#endif
