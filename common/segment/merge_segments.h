// merge_segments.h: the paper's manual "mesh segments merge": several segments become one.
//
// Input:  segment_of_face (ids per face, -1 for none) and the ids of the segments to merge; negative ids and
//         ids that occur in no face are ignored, repeats are harmless.
// Output: every face of a listed segment gets the same id, other segments keep their faces; ids are compacted
//         to 0..K-1 in their order (compact_segment_ids.h). Returns K.
// Complexity: O(F log L + L log L) for L listed ids.
#ifndef PRIMITIVE_EDIT_MERGE_SEGMENTS_H
#define PRIMITIVE_EDIT_MERGE_SEGMENTS_H

#include "common/mesh/compact_segment_ids.h"

#include <algorithm>
#include <vector>

namespace primitive_edit {

int merge_segments(std::vector<int>& segment_of_face, const std::vector<int>& segments);

} // namespace primitive_edit

#endif
