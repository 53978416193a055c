#include "common/segment/merge_segments.h"

namespace primitive_edit {

int merge_segments(std::vector<int>& segment_of_face, const std::vector<int>& segments)
{
  std::vector<int> listed(segments);
  std::sort(listed.begin(), listed.end());
  listed.erase(std::unique(listed.begin(), listed.end()), listed.end());
  int target = -1;
  for (int& s : segment_of_face) {
    if (s < 0 || !std::binary_search(listed.begin(), listed.end(), s))
      continue;
    if (target < 0)
      target = s;
    s = target;
  }
  return compact_segment_ids(segment_of_face);
}

} // namespace primitive_edit
