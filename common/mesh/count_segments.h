// count_segments.h: the number of segments K of a dense segmentation (ids 0..K-1, -1 for no segment).
//
// Input:  segment_of_face. Output: 1 + the largest id, 0 when there is none. Cost: O(F).
#ifndef PRIMITIVE_EDIT_COUNT_SEGMENTS_H
#define PRIMITIVE_EDIT_COUNT_SEGMENTS_H

#include <algorithm>
#include <vector>

namespace primitive_edit {

int count_segments(const std::vector<int>& segment_of_face);

} // namespace primitive_edit

#endif
