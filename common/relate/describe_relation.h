// describe_relation.h: one line of text for a relation, as the log shows it to the user.
//
// Input:  a Relation (relation.h) and the primitives per segment it refers to (after the joint refit).
// Output: e.g. "coaxial: segments 3 and 7 (axes 0.0021 apart)", "tangent: segment 5 (fillet, radius 1.5) and
//         segment 2", "angle: segments 0 and 4 at 45 degrees".
// Cost:   O(1).
#ifndef PRIMITIVE_EDIT_DESCRIBE_RELATION_H
#define PRIMITIVE_EDIT_DESCRIBE_RELATION_H

#include "common/relate/relation.h"

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace primitive_edit {

std::string describe_relation(const Relation& r, const std::vector<std::optional<Primitive>>& primitives);

} // namespace primitive_edit

#endif
