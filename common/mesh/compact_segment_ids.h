// compact_segment_ids.h: renumber segment ids to 0..K-1, keeping their order.
//
// Input:  segment_of_face, one id per face (indexed by vcg::tri::Index); negative ids mean "no segment".
// Output: the same partition with ids 0..K-1: the k-th smallest id becomes k, so ids that are already
//         dense are left as they are and sparse ones keep their order (a user who reads id 32 in the face
//         quality finds the same faces as segment 32 in every filter, when the ids were dense). Every negative
//         id becomes -1. Returns K.
// Complexity: O(F) when ids are below about 2F (the usual case), else O(F log F).
#ifndef PRIMITIVE_EDIT_COMPACT_SEGMENT_IDS_H
#define PRIMITIVE_EDIT_COMPACT_SEGMENT_IDS_H

#include <algorithm>
#include <cstddef>
#include <vector>

namespace primitive_edit {

int compact_segment_ids(std::vector<int>& segment_of_face);

} // namespace primitive_edit

#endif
