#include "common/mesh/count_segments.h"

namespace primitive_edit {

int count_segments(const std::vector<int>& segment_of_face)
{
  int k = 0;
  for (int s : segment_of_face)
    k = std::max(k, s + 1);
  return k;
}

} // namespace primitive_edit
