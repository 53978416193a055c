#include "common/segment/move_faces_to_new_segment.h"

namespace primitive_edit {

int move_faces_to_new_segment(std::vector<int>& segment_of_face, const std::vector<int>& faces)
{
  // Compacting first makes K a free id whatever the input ids were.
  const int new_id = compact_segment_ids(segment_of_face);
  for (int f : faces)
    if (f >= 0 && std::size_t(f) < segment_of_face.size() && segment_of_face[std::size_t(f)] >= 0)
      segment_of_face[std::size_t(f)] = new_id;
  return compact_segment_ids(segment_of_face);
}

} // namespace primitive_edit
