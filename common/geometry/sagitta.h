// sagitta.h: how far a circular arc stands off its chord.
//
// Input:  the circle's radius r and the chord's length c (both >= 0).
// Output: the sagitta r - sqrt(r^2 - c^2 / 4); a chord longer than the diameter (c > 2r) gives r, the most an arc
//         of that circle can stand off.
// Why:    a sphere or cylinder fitted to a patch whose extent is c is a plane within a tolerance when its arc over
//         the patch sags by less than it; the automatic type choice and the merge of regions judge flat fits so.
// Cost:   O(1).
#ifndef PRIMITIVE_EDIT_SAGITTA_H
#define PRIMITIVE_EDIT_SAGITTA_H

#include <algorithm>
#include <cmath>

namespace primitive_edit {

inline double sagitta(double radius, double chord)
{
  return radius - std::sqrt(std::max(0.0, radius * radius - 0.25 * chord * chord));
}

} // namespace primitive_edit

#endif
