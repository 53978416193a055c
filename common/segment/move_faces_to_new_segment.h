// move_faces_to_new_segment.h: manual split by selection: the listed faces leave their segments and form one
// new segment.
//
// Input:  segment_of_face (ids per face, -1 for deleted faces) and face indices (vcg::tri::Index). Indices out
//         of range and faces without a segment (-1, i.e. deleted) are ignored, repeats are harmless.
// Output: the listed faces share a new id; the rest of their former segments keep their ids (a former segment
//         may become disconnected; split it with split_segments_by_plane if needed). Ids compacted to 0..K-1.
//         Returns K.
// Complexity: O(F + number of listed faces).
#ifndef PRIMITIVE_EDIT_MOVE_FACES_TO_NEW_SEGMENT_H
#define PRIMITIVE_EDIT_MOVE_FACES_TO_NEW_SEGMENT_H

#include "common/mesh/compact_segment_ids.h"

#include <cstddef>
#include <vector>

namespace primitive_edit {

int move_faces_to_new_segment(std::vector<int>& segment_of_face, const std::vector<int>& faces);

} // namespace primitive_edit

#endif
