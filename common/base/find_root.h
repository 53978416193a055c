// find_root.h: the root of an element in a union-find forest.
//
// Input:  parent, one entry per element (an index into parent; parent[r] == r at a root), and an element s.
// Output: the root of s's tree. Every element on the path is re-linked to its grandparent (path halving), so
//         later finds are shorter; which elements are roots does not change.
// Cost:   O(path length); nearly constant amortised over a sequence of finds and unions.
#ifndef PRIMITIVE_EDIT_FIND_ROOT_H
#define PRIMITIVE_EDIT_FIND_ROOT_H

#include <cstddef>
#include <vector>

namespace primitive_edit {

int find_root(std::vector<int>& parent, int s);

} // namespace primitive_edit

#endif
